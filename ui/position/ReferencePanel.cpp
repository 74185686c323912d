#include "ReferencePanel.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "common/LayoutItems.h"
#include "common/LedIndicator.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineReferenceRows.h"
#include "position/ReferenceRunner.h"
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

namespace stepdeck::ui {

ReferencePanel::ReferencePanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_runner(new ReferenceRunner(context, this)),
      m_grid(new QGridLayout), m_all(new QPushButton(tr("Reference all"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)), m_progress(new QProgressBar(this)),
      m_message(new ElidedLabel(this, 2)), m_machineRows(new MachineReferenceRows(context, this))
{
    auto* layout = new QVBoxLayout(this);
    // The controller's own rows, or the machine's (read-only, from its file) while one is open.
    auto* controllerRows = new QWidget(this);
    controllerRows->setObjectName(QStringLiteral("controllerReferenceRows"));
    controllerRows->setLayout(m_grid);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_controllerRows = controllerRows;
    layout->addWidget(controllerRows);
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
    connect(m_runner, &ReferenceRunner::progress, this, &ReferencePanel::onProgress);
    connect(m_runner, &ReferenceRunner::finished, this, &ReferencePanel::onFinished);
    connect(context, &MachineContext::modelChanged, this, &ReferencePanel::rebuild);
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
    rebuild();
    showMachineOrNot();
}

void ReferencePanel::showMachineOrNot()
{
    const bool machine = m_context->hasMachine();
    m_controllerRows->setVisible(!machine);
    m_machineRows->setVisible(machine);
    m_all->setToolTip(machine ? tr("Reference every axis of the machine in the order and "
                                   "directions of its file (equal orders run together)")
                              : tr("Reference every axis in the order given (equal numbers run "
                                   "together)"));
    onStatus(m_context->status());
}

void ReferencePanel::rebuild()
{
    deleteLayoutItems(m_grid);
    m_rows.clear();
    m_grid->addWidget(new QLabel(tr("Axis"), this), 0, 0);
    m_grid->addWidget(new QLabel(tr("Direction"), this), 0, 1);
    m_grid->addWidget(new QLabel(tr("Order"), this), 0, 2);
    m_grid->addWidget(new QLabel(tr("State"), this), 0, 3);
    // Some controllers choose the direction of their reference runs themselves (EMIS 9.9).
    const bool directed = m_context->capabilities().referenceDirection;
    int r = 1;
    for (Axis axis : m_context->axes()) {
        Row row;
        row.direction = new QComboBox(this);
        if (directed) {
            row.direction->addItem(tr("\u2212 (negative)"), -1);
            row.direction->addItem(tr("+ (positive)"), 1);
        } else {
            row.direction->addItem(tr("reference"), 1);
            row.direction->setToolTip(
                tr("The controller chooses the direction of its reference run itself"));
        }
        row.direction->addItem(tr("skip"), 0);
        // The settings (MachineContext::referenceDirection); a model that picks the direction
        // itself stores 1 for "reference".
        const int stored = m_context->referenceDirection(axis);
        const int wanted = directed ? stored : (stored == 0 ? 0 : 1);
        const int index = row.direction->findData(wanted);
        row.direction->setCurrentIndex(index >= 0 ? index
                                                  : row.direction->findData(directed ? -1 : 1));
        row.order = new QSpinBox(this);
        row.order->setRange(1, 4);
        row.order->setValue(m_context->referenceOrder(axis));
        row.order->setToolTip(tr("Axes with the same number are referenced together; lower "
                                 "numbers first"));
        // The lamp alone (its state in the tooltip; the DRO says REFERENCED or UNKNOWN):
        // "unknown (no link)" beside it pushed the Reference buttons off the dock.
        row.led = new LedIndicator({}, this);
        row.run = new QPushButton(tr("Reference %1").arg(axisName(axis)), this);
        row.run->setFocusPolicy(Qt::NoFocus);
        connect(row.run, &QPushButton::clicked, this, [this, axis] { referenceAxis(axis); });
        connect(row.direction, &QComboBox::currentIndexChanged, this, &ReferencePanel::store);
        connect(row.order, &QSpinBox::valueChanged, this, &ReferencePanel::store);
        auto* name = new QLabel(axisName(axis), this);
        QFont f = name->font();
        f.setBold(true);
        name->setFont(f);
        m_grid->addWidget(name, r, 0);
        m_grid->addWidget(row.direction, r, 1);
        m_grid->addWidget(row.order, r, 2);
        m_grid->addWidget(row.led, r, 3, Qt::AlignCenter);
        m_grid->addWidget(row.run, r, 4);
        m_rows.insert(axis, row);
        ++r;
    }
    onStatus(m_context->status());
}

void ReferencePanel::store()
{
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it)
        m_context->setReference(it.key(), it.value().direction->currentData().toInt(),
                                it.value().order->value());
}

QMap<Axis, int> ReferencePanel::directions() const
{
    QMap<Axis, int> out;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it)
        out.insert(it.key(), it.value().direction->currentData().toInt());
    return out;
}

QMap<Axis, int> ReferencePanel::order() const
{
    QMap<Axis, int> out;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it)
        out.insert(it.key(), it.value().order->value());
    return out;
}

QString ReferencePanel::messageText() const
{
    return m_message->text();
}

void ReferencePanel::referenceAll()
{
    if (machine::Machine* m = m_context->machine()) {
        referenceMachine(m, {});
        return;
    }
    m_runner->start(ReferenceRunner::plan(directions(), order()));
}

// With a machine open, "Reference all" is the machine's: every axis of every controller in the
// file's order and directions (Machine::reference), not this panel's per-controller plan.
void ReferencePanel::referenceMachine(machine::Machine* m, const QStringList& axes)
{
    if (m_listenedMachine != m)
        listenTo(m);
    QString refusal;
    m_machineRun = m->reference(axes, &refusal);
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
                if (id != m_machineRun)
                    return;
                m_machineRows->setRunningAxes(axes);
                onProgress(0, 1, tr("Referencing %1\u2026").arg(axes.join(QStringLiteral(", "))));
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
                onFinished(ok, ok ? done : tr("Referencing failed: %1").arg(message));
            });
}

void ReferencePanel::referenceAxis(Axis axis)
{
    int direction = directions().value(axis);
    if (direction == 0)
        direction = m_context->capabilities().referenceDirection ? -1 : 1; // the default
    m_runner->start({ReferenceRunner::Stage{{axis, direction}}});
}

void ReferencePanel::cancel()
{
    m_context->stop();
    m_runner->cancel(tr("Referencing cancelled."));
}

void ReferencePanel::onStatus(const MachineStatus& status)
{
    // Referencing needs a connection (with a machine: any of its controllers; the machine
    // refuses a run whose controller is not connected, saying which) and no run in progress.
    const bool live = machineConnected() || m_context->isConnected();
    const bool idle = !m_runner->isRunning() && m_machineRun == 0;
    m_all->setEnabled(live && idle);
    m_machineRows->setRunsEnabled(live && idle);
    for (const Row& row : std::as_const(m_rows))
        row.run->setEnabled(live && idle);
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        const AxisStatus a = status.axes.value(it.key());
        const bool running = m_runner->currentAxes().contains(it.key());
        LedIndicator* led = it.value().led;
        if (!live) {
            led->setState(LedIndicator::State::Unknown);
            setToolTipIfChanged(led, tr("unknown (no link)"));
        } else if (running) {
            led->setState(LedIndicator::State::Warning);
            setToolTipIfChanged(led, tr("referencing\u2026"));
        } else {
            led->setOn(a.referenced);
            setToolTipIfChanged(led, a.referenced ? tr("referenced") : tr("not referenced"));
        }
    }
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
    m_cancel->setEnabled(m_runner->isRunning());
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
    if (!ok)
        m_progress->setValue(0);
    m_cancel->setEnabled(false);
    onStatus(m_context->status());
}

} // namespace stepdeck::ui
