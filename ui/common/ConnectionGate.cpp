#include "ConnectionGate.h"
#include "machine/MachineContext.h"
#include <QAction>
#include <QWidget>

namespace stepdeck::ui {

ConnectionGate::ConnectionGate(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context)
{
    connect(context->session(), &ControllerSession::linkStateChanged, this,
            &ConnectionGate::refresh);
    connect(context, &MachineContext::modelChanged, this, &ConnectionGate::refresh);
}

void ConnectionGate::add(QWidget* widget)
{
    m_widgets << widget;
    widget->setEnabled(isOpen());
}

void ConnectionGate::add(QAction* action)
{
    m_actions << action;
    action->setEnabled(isOpen());
}

bool ConnectionGate::isOpen() const
{
    return m_context->isConnected();
}

void ConnectionGate::refresh()
{
    const bool open = isOpen();
    for (const QPointer<QWidget>& w : std::as_const(m_widgets)) {
        if (w)
            w->setEnabled(open);
    }
    for (const QPointer<QAction>& a : std::as_const(m_actions)) {
        if (a)
            a->setEnabled(open);
    }
    Q_EMIT changed(open);
}

} // namespace stepdeck::ui
