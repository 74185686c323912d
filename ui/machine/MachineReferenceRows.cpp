#include "MachineReferenceRows.h"
#include "MachineContext.h"
#include "common/IfChanged.h"
#include "common/LayoutItems.h"
#include "common/LedIndicator.h"
#include "machine/Machine.h"
#include "protocols/Registry.h"
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace stepdeck::ui {

MachineReferenceRows::MachineReferenceRows(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_grid(new QGridLayout(this))
{
    setObjectName(QStringLiteral("machineReferenceRows"));
    m_grid->setContentsMargins(0, 0, 0, 0);
    connect(context, &MachineContext::machineChanged, this, &MachineReferenceRows::rebuild);
    connect(context, &MachineContext::machineStatusChanged, this, &MachineReferenceRows::refresh);
    rebuild();
}

QString MachineReferenceRows::directionText(const QString& axis) const
{
    const Row row = m_rows.value(axis);
    return row.direction ? row.direction->text() : QString();
}

QString MachineReferenceRows::orderText(const QString& axis) const
{
    const Row row = m_rows.value(axis);
    return row.order ? row.order->text() : QString();
}

QPushButton* MachineReferenceRows::runButton(const QString& axis) const
{
    return m_rows.value(axis).run;
}

void MachineReferenceRows::setRunsEnabled(bool enabled)
{
    for (const Row& row : std::as_const(m_rows))
        row.run->setEnabled(enabled);
}

void MachineReferenceRows::setRunningAxes(const QStringList& running)
{
    m_running = running;
    refresh();
}

void MachineReferenceRows::rebuild()
{
    deleteLayoutItems(m_grid);
    m_rows.clear();
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    m_grid->addWidget(new QLabel(tr("Axis"), this), 0, 0);
    m_grid->addWidget(new QLabel(tr("Direction"), this), 0, 1);
    m_grid->addWidget(new QLabel(tr("Order"), this), 0, 2);
    m_grid->addWidget(new QLabel(tr("State"), this), 0, 3);
    int r = 1;
    for (const machine::MachineAxis& a : m->description().axes) {
        const machine::MachineController* c = m->description().controller(a.controller);
        const ModelInfo* model = c ? findModel(c->modelId) : nullptr;
        // The direction as the run uses it (MachineReferenceRun): the file's, negative when
        // the file gives none, or none where the controller chooses it itself (EMIS 9.9).
        const bool directed = model && model->capabilities.referenceDirection;
        Row row;
        row.direction = new QLabel(!directed                  ? tr("controller chooses")
                                   : a.referenceDirection > 0 ? tr("+ (positive)")
                                                              : tr("\u2212 (negative)"),
                                   this);
        row.order = new QLabel(QString::number(a.referenceOrder), this);
        const QString tip =
            tr("The machine's referencing: edit it with File \u2192 Edit machine\u2026");
        row.direction->setToolTip(tip);
        row.order->setToolTip(tip);
        row.led = new LedIndicator({}, this);
        row.run = new QPushButton(tr("Reference %1").arg(a.name), this);
        row.run->setFocusPolicy(Qt::NoFocus);
        const QString name = a.name;
        connect(row.run, &QPushButton::clicked, this,
                [this, name] { Q_EMIT referenceRequested({name}); });
        auto* label = new QLabel(a.name, this);
        QFont f = label->font();
        f.setBold(true);
        label->setFont(f);
        m_grid->addWidget(label, r, 0);
        m_grid->addWidget(row.direction, r, 1);
        m_grid->addWidget(row.order, r, 2);
        m_grid->addWidget(row.led, r, 3, Qt::AlignCenter);
        m_grid->addWidget(row.run, r, 4);
        m_rows.insert(a.name, row);
        ++r;
    }
    refresh();
}

void MachineReferenceRows::refresh()
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineAxis& a : m->description().axes) {
        LedIndicator* led = m_rows.value(a.name).led;
        if (!led)
            continue;
        const ControllerSession* s = m->session(a.controller);
        const bool live = s && s->isCreated() && s->linkState() == LinkState::Connected;
        if (!live) {
            led->setState(LedIndicator::State::Unknown);
            setToolTipIfChanged(led, tr("unknown (no link)"));
        } else if (m_running.contains(a.name)) {
            led->setState(LedIndicator::State::Warning);
            setToolTipIfChanged(led, tr("referencing\u2026"));
        } else {
            const bool referenced =
                m->axisStatus(a).known == machine::PositionKnowledge::Referenced;
            led->setOn(referenced);
            setToolTipIfChanged(led, referenced ? tr("referenced") : tr("not referenced"));
        }
    }
}

} // namespace stepdeck::ui
