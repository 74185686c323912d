#include "GoToWidget.h"
#include "common/ElidedLabel.h"
#include "machine/MachineContext.h"
#include <QDoubleValidator>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace stepdeck::ui {

GoToWidget::GoToWidget(MachineContext* context, QWidget* parent)
    : QGroupBox(tr("Go to position"), parent), m_context(context), m_fields(new QWidget(this)),
      m_go(new QPushButton(tr("Go"), this)), m_zero(new QPushButton(tr("Go to work zero"), this)),
      m_message(new ElidedLabel(this, 2))
{
    setObjectName(QStringLiteral("goToPosition"));
    m_go->setToolTip(tr("Move the axes with a value to that work position (all at once)"));
    m_zero->setToolTip(tr("Move every axis to its work zero (all at once)"));
    // Two lines reserved, longer reasons elided with the full text in the tooltip: a message
    // never moves the fields and buttons around it (issue 16).
    m_message->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
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
    connect(session, &ControllerSession::statusChanged, this, &GoToWidget::followMove);
    rebuild();
}

bool GoToWidget::eventFilter(QObject* watched, QEvent* event)
{
    // Enter in a target field is the Go button (issue 16), with the button's checks: nothing
    // moves while the button could not be pressed (its reason is on show then).
    if (event->type() == QEvent::KeyPress && watched->parent() == m_fields) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            if (m_go->isEnabled())
                goToTargets();
            else
                refresh();
            return true;
        }
    }
    return QGroupBox::eventFilter(watched, event);
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
        edit->installEventFilter(this);
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

QString GoToWidget::refusal() const
{
    // For a referenced machine at rest only: an absolute target means nothing otherwise, and
    // a new target while an axis moves would replace a move the operator did not end.
    if (!m_context->isConnected())
        return tr("Not connected.");
    const MachineStatus& status = m_context->status();
    for (Axis axis : m_context->axes()) {
        if (!status.axes.value(axis).referenced)
            return tr("Reference the machine to go to a position (axis %1 is not referenced).")
                .arg(axisName(axis));
    }
    bool moving = status.busy || status.motionUnconfirmed;
    for (const AxisStatus& a : status.axes)
        moving = moving || a.moving || a.jogging || a.motionUnknown;
    if (moving)
        return tr("The machine is moving: go to a position once it stands still.");
    return {};
}

void GoToWidget::refresh()
{
    const QString why = m_context->isConnected() ? refusal() : QString();
    const bool ready = why.isEmpty() && m_context->isConnected() && !m_context->axes().isEmpty();
    m_go->setEnabled(ready && !m_pending);
    m_zero->setEnabled(ready && !m_pending);
    // The reason stays on screen while it holds; a result of the last move is kept.
    if (!why.isEmpty() && !m_pending && (m_message->text().isEmpty() || m_showingReason)) {
        m_message->setStyleSheet(QString());
        m_message->setText(why);
        m_showingReason = true;
    } else if (why.isEmpty() && m_showingReason) {
        m_message->clear();
        m_showingReason = false;
    }
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
            m_showingReason = false;
            return;
        }
        targets.insert(it.key(), m_context->toMachineSteps(it.key(), value));
        shown << QStringLiteral("%1 %2").arg(axisName(it.key()), text);
    }
    if (targets.isEmpty()) {
        m_message->setText(tr("Enter a position for at least one axis."));
        m_showingReason = false;
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
    if (const QString why = refusal(); !why.isEmpty()) {
        m_message->setText(why);
        m_showingReason = true;
        return;
    }
    m_showingReason = false;
    m_pending = m_context->session()->moveAbsolute(machineTargets);
    m_following.clear();
    m_sentAxes = machineTargets.keys();
    m_message->setStyleSheet(QString());
    m_message->setText(tr("Moving to %1\u2026").arg(what));
    refresh();
}

void GoToWidget::onResult(const CommandResult& result)
{
    if (result.id != m_pending || !m_pending)
        return;
    m_pending = 0;
    m_showingReason = false;
    if (!result.ok()) {
        m_message->setStyleSheet(QStringLiteral("QLabel { color: #c62828; }"));
        m_message->setText(tr("Not moved: %1").arg(result.message));
    } else if (m_context->capabilities().reportsArrival) {
        // The request ended with the axes' own report of arrival.
        m_message->setText(tr("Target reached: the controller reported the arrival."));
    } else {
        m_message->setText(tr("Move accepted by the controller."));
        m_following = m_sentAxes; // true until the move ends (followMove)
        followMove(m_context->status());
    }
    refresh();
}

void GoToWidget::followMove(const MachineStatus& status)
{
    if (m_following.isEmpty())
        return;
    if (!m_context->isConnected()) {
        m_following.clear();
        return;
    }
    // Ended only by the controller's word: every axis of the move reported standing still.
    if (status.busy || status.motionUnconfirmed)
        return;
    for (Axis axis : std::as_const(m_following)) {
        const AxisStatus a = status.axes.value(axis);
        if (a.moving || a.motionUnknown)
            return;
    }
    m_following.clear();
    m_message->setStyleSheet(QString());
    m_message->setText(tr("The move has ended: the controller reports the axes at standstill."));
}

} // namespace stepdeck::ui
