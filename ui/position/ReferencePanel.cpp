#include "ReferencePanel.h"
#include "common/ElidedLabel.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineReferenceRows.h"
#include <QBoxLayout>
#include <QProgressBar>
#include <QPushButton>

namespace stepdeck::ui {

ReferencePanel::ReferencePanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_all(new QPushButton(tr("Reference all"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)), m_progress(new QProgressBar(this)),
      m_message(new ElidedLabel(this, 2)), m_machineRows(new MachineReferenceRows(context, this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_machineRows);
    auto* row = new QHBoxLayout;
    row->addWidget(m_all, 1);
    row->addWidget(m_cancel);
    layout->addLayout(row);
    layout->addWidget(m_progress);
    layout->addWidget(m_message);
    layout->addStretch(1);
    m_all->setObjectName(QStringLiteral("referenceAll"));
    m_cancel->setEnabled(false);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    // Two lines reserved, longer messages elided (the full text in the tooltip): a message
    // never moves what is below it (issue 16).
    m_message->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    for (QPushButton* b : {m_all, m_cancel})
        b->setFocusPolicy(Qt::NoFocus);

    connect(m_all, &QPushButton::clicked, this, &ReferencePanel::referenceAll);
    connect(m_cancel, &QPushButton::clicked, this, &ReferencePanel::cancel);
    connect(context->session(), &ControllerSession::statusChanged, this, &ReferencePanel::onStatus);
    connect(context->session(), &ControllerSession::linkStateChanged, this,
            [this] { onStatus(m_context->status()); });
    connect(context, &MachineContext::panicTriggered, this,
            [this] { invalidateSuccess(tr("the panic stop")); });
    connect(context, &MachineContext::machineChanged, this, &ReferencePanel::showMachineOrNot);
    connect(context, &MachineContext::machineStatusChanged, this,
            [this] { onStatus(m_context->status()); });
    connect(m_machineRows, &MachineReferenceRows::referenceRequested, this,
            [this](const QStringList& axes) {
                if (machine::Machine* m = m_context->machine())
                    referenceMachine(m, axes);
            });
    showMachineOrNot();
}

void ReferencePanel::showMachineOrNot()
{
    m_all->setToolTip(tr("Reference every axis of the machine in the order and directions of "
                         "its description (equal orders run together)"));
    onStatus(m_context->status());
}

QString ReferencePanel::messageText() const
{
    return m_message->text();
}

void ReferencePanel::referenceAll()
{
    if (machine::Machine* m = m_context->machine())
        referenceMachine(m, {});
}

// Every axis of every controller in the description's order and directions
// (Machine::reference).
void ReferencePanel::referenceMachine(machine::Machine* m, const QStringList& axes)
{
    if (m_listenedMachine != m)
        listenTo(m);
    // The bar counts the groups (equal orders run together) the machine confirmed: no more
    // is known of how far a run to a switch has come.
    QSet<int> orders;
    for (const machine::MachineAxis& a : m->description().axes)
        if (axes.isEmpty() || axes.contains(a.name))
            orders.insert(a.referenceOrder);
    m_groups = int(qMax(qsizetype(1), orders.size()));
    m_groupsStarted = 0;
    onProgress(0, m_groups, tr("Referencing\u2026"));
    QString refusal;
    // The first group may start inside reference(), before its id is known here.
    m_startingRun = true;
    m_machineRun = m->reference(axes, &refusal);
    m_startingRun = false;
    m_machineRunAxes = axes;
    if (m_machineRun == 0) {
        onFinished(false, tr("Referencing refused: %1").arg(refusal));
        return;
    }
    m_cancel->setEnabled(true);
    onStatus(m_context->status());
}

void ReferencePanel::listenTo(machine::Machine* m)
{
    m_listenedMachine = m;
    connect(m, &machine::Machine::referenceGroupStarted, this,
            [this](quint64 id, const QStringList& axes) {
                if (id != m_machineRun && !m_startingRun)
                    return;
                m_machineRows->setRunningAxes(axes);
                // The groups before this one ended referenced.
                onProgress(m_groupsStarted++, m_groups,
                           tr("Referencing %1\u2026").arg(axes.join(QStringLiteral(", "))));
            });
    connect(m, &machine::Machine::referenceFinished, this,
            [this](quint64 id, bool ok, const QString& message) {
                if (id != m_machineRun)
                    return;
                m_machineRun = 0;
                m_machineRows->setRunningAxes({});
                const QString done =
                    m_machineRunAxes.isEmpty()
                        ? tr("Every axis of the machine is referenced.")
                        : tr("%1 referenced.").arg(m_machineRunAxes.join(QStringLiteral(", ")));
                if (ok)
                    onProgress(m_groups, m_groups, done);
                onFinished(ok, ok ? done : tr("Referencing failed: %1").arg(message));
            });
}

void ReferencePanel::cancel()
{
    // Said first: the machine ends its run inside stop(), and that failure is this cancel.
    stopped(tr("Referencing cancelled."));
    m_context->stop();
}

void ReferencePanel::stopped(const QString& message)
{
    if (m_machineRun == 0)
        return;
    m_machineRun = 0; // its failure, when it arrives, is this stop's
    m_machineRows->setRunningAxes({});
    onFinished(false, message);
}

void ReferencePanel::onStatus(const MachineStatus& status)
{
    // Referencing needs a connection (any of the machine's controllers; the machine refuses a
    // run whose controller is not connected, saying which) and no run in progress.
    const bool live = machineConnected();
    const bool idle = m_machineRun == 0;
    m_all->setEnabled(live && idle);
    m_machineRows->setRunsEnabled(live && idle);
    // "All selected axes are referenced" holds only while they are.
    if (!live) {
        invalidateSuccess(tr("the link is down"));
    } else {
        for (Axis axis : std::as_const(m_successAxes)) {
            if (!status.axes.value(axis).referenced) {
                invalidateSuccess(tr("a panic stop, reset or limit switch"));
                break;
            }
        }
    }
}

bool ReferencePanel::machineConnected() const
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return false;
    for (const machine::MachineController& c : m->description().controllers) {
        const ControllerSession* s = m->session(c.id);
        if (s && s->isCreated() && s->linkState() == LinkState::Connected)
            return true;
    }
    return false;
}

void ReferencePanel::invalidateSuccess(const QString& cause)
{
    if (m_successAxes.isEmpty())
        return;
    m_successAxes.clear();
    m_message->setText(
        tr("The axes are no longer referenced (%1): reference them again.").arg(cause));
    m_message->setStyleSheet(QStringLiteral("QLabel { color: #b26a00; font-weight: bold; }"));
    m_progress->setValue(0);
}

void ReferencePanel::onProgress(int stage, int stages, const QString& text)
{
    m_progress->setRange(0, stages);
    m_progress->setValue(stage);
    m_message->setText(text);
    m_message->setStyleSheet(QString());
    m_cancel->setEnabled(m_machineRun != 0);
    onStatus(m_context->status());
}

void ReferencePanel::onFinished(bool ok, const QString& message)
{
    m_successAxes.clear();
    if (ok) {
        for (auto it = m_context->status().axes.cbegin(); it != m_context->status().axes.cend();
             ++it) {
            if (it.value().referenced)
                m_successAxes << it.key();
        }
    }
    m_message->setText(message);
    m_message->setStyleSheet(ok ? QStringLiteral("QLabel { color: #2e7d32; }")
                                : QStringLiteral("QLabel { color: #c62828; font-weight: bold; }"));
    // A run that succeeded is complete whatever stage was reported last (issue 31: the bar
    // stayed at 0 % after success); a failed one starts over.
    m_progress->setValue(ok ? m_progress->maximum() : 0);
    m_cancel->setEnabled(false);
    onStatus(m_context->status());
}

} // namespace stepdeck::ui
