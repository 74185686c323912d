#pragma once
#include <QList>
#include <QObject>
#include <QPointer>

class QAction;
class QWidget;

namespace stepdeck::ui {

class MachineContext;

// Controls that need a connection are disabled while there is none (issue 11): a page adds
// its widgets and actions here once; they follow the link state. A control that is also
// disabled for another reason as well checks isOpen() itself.
class ConnectionGate : public QObject
{
    Q_OBJECT
public:
    explicit ConnectionGate(MachineContext* context, QObject* parent = nullptr);

    void add(QWidget* widget);
    void add(QAction* action);
    bool isOpen() const;
    void refresh();

Q_SIGNALS:
    void changed(bool connected);

private:
    MachineContext* m_context;
    QList<QPointer<QWidget>> m_widgets;
    QList<QPointer<QAction>> m_actions;
};

} // namespace stepdeck::ui
