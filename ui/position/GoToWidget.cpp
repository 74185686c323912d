#include "GoToWidget.h"
#include "main/MachineContext.h"
#include <QDoubleValidator>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace stepdeck::ui {

GoToWidget::GoToWidget(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Go to position"), parent), m_context(context), m_fields(new QWidget(this)),
      m_go(new QPushButton(tr("Go"), this)), m_zero(new QPushButton(tr("Go to work zero"), this)),
      m_message(new QLabel(this))
{
    setObjectName(QStringLiteral("goToPosition"));
    m_go->setToolTip(tr("Move the axes with a value to that work position (all at once)"));
    m_zero->setToolTip(tr("Move every axis to its work zero (all at once)"));
    m_message->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_fields);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_go);
    buttons->addWidget(m_zero);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    layout->addWidget(m_message);
    connect(m_go, &QPushButton::clicked, this, &GoToWidget::goToTargets);
    connect(m_zero, &QPushButton::clicked, this, &GoToWidget::goToWorkZero);
    connect(context, &MachineContext::modelChanged, this, &GoToWidget::rebuild);
    connect(context, &MachineContext::unitsChanged, this, &GoToWidget::rebuild);
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::statusChanged, this, &GoToWidget::refresh);
    connect(session, &ControllerSession::linkStateChanged, this, &GoToWidget::refresh);
    connect(session, &ControllerSession::requestFinished, this, &GoToWidget::onResult);
    rebuild();
}

QString GoToWidget::messageText() const
{
    return m_message->text();
}

void GoToWidget::rebuild()
{
    delete m_fields->layout();
    qDeleteAll(m_fields->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly));
    m_targets.clear();
    auto* grid = new QGridLayout(m_fields);
    grid->setContentsMargins(0, 0, 0, 0);
    int column = 0;
    for (Axis axis : m_context->axes()) {
        auto* edit = new QLineEdit(m_fields);
        edit->setValidator(new QDoubleValidator(edit));
        edit->setAlignment(Qt::AlignRight);
        edit->setPlaceholderText(m_context->unitName(axis));
        edit->setToolTip(tr("Work position of %1 in %2; empty: %1 stays")
                             .arg(axisName(axis), m_context->unitName(axis)));
        grid->addWidget(new QLabel(axisName(axis), m_fields), 0, column);
        grid->addWidget(edit, 0, column + 1);
        m_targets.insert(axis, edit);
        column += 2;
    }
    refresh();
}

void GoToWidget::refresh()
{
    // For a referenced machine only: an absolute target means nothing otherwise.
    bool referenced = m_context->isConnected() && !m_context->axes().isEmpty();
    for (Axis axis : m_context->axes())
        referenced = referenced && m_context->status().axes.value(axis).referenced;
    m_go->setEnabled(referenced && !m_pending);
    m_zero->setEnabled(referenced && !m_pending);
    if (!referenced && m_context->isConnected() && m_message->text().isEmpty())
        m_message->setText(tr("Reference the machine to go to a position."));
    else if (referenced && m_message->property("referenceHint").toBool())
        m_message->clear();
    m_message->setProperty("referenceHint", !referenced);
}

void GoToWidget::goToTargets()
{
    AxisVector targets;
    QStringList shown;
    for (auto it = m_targets.cbegin(); it != m_targets.cend(); ++it) {
        const QString text = it.value()->text().trimmed();
        if (text.isEmpty())
            continue;
        bool ok = false;
        const double value = QLocale().toDouble(text, &ok);
        if (!ok) {
            m_message->setText(tr("%1: '%2' is not a number").arg(axisName(it.key()), text));
            return;
        }
        targets.insert(it.key(), m_context->toMachineSteps(it.key(), value));
        shown << QStringLiteral("%1 %2").arg(axisName(it.key()), text);
    }
    if (targets.isEmpty()) {
        m_message->setText(tr("Enter a position for at least one axis."));
        return;
    }
    send(targets, shown.join(QStringLiteral(", ")));
}

void GoToWidget::goToWorkZero()
{
    AxisVector targets;
    for (Axis axis : m_context->axes())
        targets.insert(axis, m_context->units(axis).workOffset);
    send(targets, tr("work zero"));
}

void GoToWidget::send(const AxisVector& machineTargets, const QString& what)
{
    m_pending = m_context->session()->moveAbsolute(machineTargets);
    m_message->setStyleSheet(QString());
    m_message->setText(tr("Moving to %1\u2026").arg(what));
    refresh();
}

void GoToWidget::onResult(const CommandResult& result)
{
    if (result.id != m_pending || !m_pending)
        return;
    m_pending = 0;
    if (!result.ok()) {
        m_message->setStyleSheet(QStringLiteral("QLabel { color: #c62828; }"));
        m_message->setText(tr("Not moved: %1").arg(result.message));
    } else {
        m_message->setText(tr("Move accepted by the controller."));
    }
    refresh();
}

} // namespace stepdeck::ui
