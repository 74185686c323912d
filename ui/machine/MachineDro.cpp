#include "MachineDro.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineMoveTracker.h"
#include "position/DroValueLabel.h"
#include "program/MachineWorkOffsets.h"
#include <QComboBox>
#include <QCoreApplication>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QToolButton>

namespace stepdeck::ui {

namespace {
const QString kRed = QStringLiteral("background:#ffcdd2; color:#8e0000;");
const QString kAmber = QStringLiteral("background:#ffe082; color:#4e3400;");
const QString kGreen = QStringLiteral("background:#c8e6c9; color:#1b5e20;");
const QString kGrey = QStringLiteral("background:#eceff1; color:#37474f;");

QString format(const machine::MachineAxis& axis, double value)
{
    return axis.unit == machine::AxisUnit::Step ? QString::number(qRound64(value))
                                                : QString::number(value, 'f', 3);
}
} // namespace

MachineDro::MachineDro(MachineContext* context, program::MachineWorkOffsets* offsets,
                       QWidget* parent)
    : QWidget(parent), m_context(context), m_offsets(offsets), m_grid(new QGridLayout),
      m_system(new QComboBox(this)), m_clear(new QToolButton(this)),
      m_message(new ElidedLabel(this)), m_moves(new MachineMoveTracker),
      m_moveTick(new QTimer(this))
{
    m_moveTick->setInterval(100);
    connect(m_moveTick, &QTimer::timeout, this, &MachineDro::refresh);
    setObjectName(QStringLiteral("machineDro"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_grid->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(m_grid);
    // Clear and the zero's message share one line; the message elides (one line reserved).
    auto* bottom = new QHBoxLayout;
    m_system->setObjectName(QStringLiteral("machineCoordinateSystem"));
    for (int i = 0; i < program::kCoordinateSystems; ++i)
        m_system->addItem(program::coordinateSystemWord(i));
    m_system->setToolTip(tr("The coordinate system shown, zeroed by Zero, used by Go to and by "
                            "programs without G54..G59"));
    m_system->setFocusPolicy(Qt::NoFocus);
    m_system->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_system->setCurrentIndex(offsets->active());
    connect(m_system, &QComboBox::activated, offsets, &program::MachineWorkOffsets::setActive);
    bottom->addWidget(m_system);
    m_clear->setText(tr("Clear work offsets"));
    m_clear->setToolTip(tr("Show machine positions again (work origin = machine origin)"));
    m_clear->setFocusPolicy(Qt::NoFocus);
    m_message->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    bottom->addWidget(m_clear);
    bottom->addWidget(m_message, 1);
    layout->addLayout(bottom);
    connect(m_clear, &QToolButton::clicked, this, &MachineDro::clearOffsets);
    connect(offsets, &program::MachineWorkOffsets::changed, this, [this] {
        m_system->setCurrentIndex(m_offsets->active());
        refresh();
    });
    connect(context, &MachineContext::machineChanged, this, &MachineDro::rebuild);
    connect(context, &MachineContext::machineStatusChanged, this, &MachineDro::refresh);
    rebuild();
}

MachineDro::~MachineDro()
{
    delete m_moves;
}

QStringList MachineDro::stateWords()
{
    return {tr("NO LINK"), tr("MOVING"), tr("UNKNOWN"), tr("ESTIMATED"), tr("REFERENCED")};
}

void MachineDro::rebuild()
{
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        if (QLayout* inner = item->layout()) { // a row's detail line
            while (QLayoutItem* sub = inner->takeAt(0)) {
                delete sub->widget();
                delete sub;
            }
        }
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    m_moves->clear();
    m_message->clear();
    m_refusedAxis.clear();
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    QFont big(QStringLiteral("monospace"));
    big.setStyleHint(QFont::Monospace);
    big.setPointSizeF(font().pointSizeF() * 2.2);
    big.setBold(true);
    QFont nameFont = font();
    nameFont.setPointSizeF(font().pointSizeF() * 2.0);
    nameFont.setBold(true);
    QFont badgeFont = font();
    badgeFont.setBold(true);
    int badgeWidth = 0;
    for (const QString& word : stateWords())
        badgeWidth = qMax(badgeWidth, QFontMetrics(badgeFont).horizontalAdvance(word) + 12);
    int r = 0;
    for (const machine::MachineAxis& axis : m->description().axes) {
        auto* name = new QLabel(axis.name, this);
        name->setFont(nameFont);
        Row row{new DroValueLabel(this), new QLabel(this), new ElidedLabel(this)};
        row.value->setObjectName(QStringLiteral("machineDroValue") + axis.name);
        row.value->setDigitFont(big);
        row.value->setUnit(unitOf(axis));
        row.value->setReservedText(axis.unit == machine::AxisUnit::Step
                                       ? QStringLiteral("\u2248-0000000")
                                       : QStringLiteral("\u2248-00000.000"));
        row.state->setAlignment(Qt::AlignCenter);
        row.state->setFixedWidth(badgeWidth);
        row.detail->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        row.detail->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
        m_grid->addWidget(name, 2 * r, 0, 2, 1);
        m_grid->addWidget(row.value, 2 * r, 1);
        m_grid->addWidget(row.state, 2 * r, 2);
        auto* zero = new QToolButton(this);
        zero->setObjectName(QStringLiteral("machineZero") + axis.name);
        zero->setText(tr("Zero %1").arg(axis.name));
        zero->setToolTip(tr("Set the work origin of %1 at the current position").arg(axis.name));
        zero->setFocusPolicy(Qt::NoFocus);
        const QString axisId = axis.name;
        connect(zero, &QToolButton::clicked, this, [this, axisId] { zeroAxis(axisId); });
        auto* detail = new QHBoxLayout;
        detail->setContentsMargins(0, 0, 0, 0);
        detail->addWidget(row.detail, 1);
        detail->addWidget(zero);
        m_grid->addLayout(detail, 2 * r + 1, 1, 1, 2);
        m_rows.insert(axis.name, row);
        ++r;
    }
    m_grid->setColumnStretch(1, 1);
    refresh();
}

void MachineDro::refresh()
{
    const machine::Machine* m = m_context->machine();
    if (!m)
        return;
    for (const machine::MachineAxis& axis : m->description().axes) {
        const ControllerSession* s = m->session(axis.controller);
        const bool linked = s && s->linkState() == LinkState::Connected;
        const machine::MachineAxisStatus status = m->axisStatus(axis);
        showAxis(m_rows.value(axis.name), status, linked);
        // "Position unknown" or "moving" no longer holds: the refusal leaves the line.
        if (axis.name == m_refusedAxis && status.known != machine::PositionKnowledge::Unknown &&
            !status.moving) {
            m_message->clear();
            m_refusedAxis.clear();
        }
    }
    if (m_moves->anyMoving() && !m_moveTick->isActive())
        m_moveTick->start();
    else if (!m_moves->anyMoving())
        m_moveTick->stop();
}

QString MachineDro::countWord(const machine::MachineAxis& axis) const
{
    return m_context->axisCountName(axis);
}

QString MachineDro::unitOf(const machine::MachineAxis& axis) const
{
    return m_context->axisUnitName(axis);
}

MoveProfile MachineDro::rampOf(const machine::MachineAxis& axis) const
{
    // The E-LAB ramp parameters by their schema names, as written or read in this session
    // (known for the selected controller: the only one of a connection's machine).
    if (axis.controller != m_context->selectedController())
        return {};
    const ParameterSet& known = m_context->knownParameters();
    auto value = [&](const char* name) {
        return known.value(QString::fromLatin1(name)).perAxis.value(axis.axis).toDouble();
    };
    return {value("start-speed"), value("max-speed"), value("acceleration")};
}

bool MachineDro::showMoveWithoutReadback(const Row& row, const machine::MachineAxisStatus& a)
{
    const machine::MachineAxis& axis = *a.axis;
    const ControllerSession* s = m_context->machine()->session(axis.controller);
    const bool readback = s && s->capabilities().positionReadback;
    // A positioning move only: a jog's count is the host's integration of its rates, not a
    // target (it is marked estimated as such).
    const AxisStatus st = s ? s->status().axes.value(axis.axis) : AxisStatus{};
    const bool positioning = st.moving && !st.jogging;
    const bool track = !readback && a.known != machine::PositionKnowledge::Unknown;
    const std::optional<MachineMoveTracker::Shown> shown =
        m_moves->update(axis.name, a.steps, track && positioning, rampOf(axis));
    if (!shown)
        return false;
    // The core counts the target already: where the axis probably is, else where it heads.
    const QString target = format(axis, m_offsets->toWork(axis.name, axis.toUnits(shown->target)));
    row.value->setText(
        shown->estimate
            ? QStringLiteral("\u2248") +
                  format(axis, m_offsets->toWork(axis.name, axis.toUnits(*shown->estimate)))
            : QStringLiteral("\u2192") + target);
    row.detail->setText(tr("moving to %1 %2 (machine %3 %4)")
                            .arg(target, unitOf(axis))
                            .arg(shown->target)
                            .arg(countWord(axis)));
    setState(row, tr("MOVING"), kAmber, !shown->estimate,
             shown->estimate
                 ? tr("Estimated from the ramp parameters; the controller reports no position "
                      "during a move. The target is shown below.")
                 : tr("The controller reports no position during a move and the ramp "
                      "parameters are not known in this session: the target is shown (\u2192), "
                      "not where the axis is now."));
    return true;
}

void MachineDro::showAxis(const Row& row, const machine::MachineAxisStatus& a, bool linked)
{
    if (!row.value || !a.axis)
        return;
    const machine::MachineAxis& axis = *a.axis;
    const QString controllerAxis =
        m_context->machine() ? m_context->machine()->description().controllerAxisName(axis)
                             : axisName(axis.axis);
    // The digits: the work position once a work zero is set, as certain as the machine
    // position it comes from (same mark, same badge); the line below: the machine position.
    const bool work = m_offsets->hasOffset(axis.name);
    QString text = format(axis, m_offsets->toWork(axis.name, a.position));
    row.value->setUnit(work ? tr("%1 work").arg(unitOf(axis)) : unitOf(axis));
    row.value->setToolTip(
        work ? tr("Work position: the machine position minus the work zero of "
                  "%1 (machine %2 %3)")
                   .arg(axis.name, format(axis, m_offsets->offset(axis.name)), unitOf(axis))
             : tr("Machine position (no work zero set for %1)").arg(axis.name));
    // An axis in the controller's count says it once (the line must fit a 1366 px screen
    // in German, issue 16).
    row.detail->setText(
        axis.unit == machine::AxisUnit::Step
            ? tr("machine %1 %2 (%3 %4)")
                  .arg(format(axis, a.position), unitOf(axis), axis.controller, controllerAxis)
            : tr("machine %1 %2, %3 axis %4: %5 %6")
                  .arg(format(axis, a.position), unitOf(axis), axis.controller, controllerAxis)
                  .arg(a.steps)
                  .arg(countWord(axis)));
    if (!linked) {
        m_moves->forget(axis.name);
        row.value->setText(text);
        setState(row, tr("NO LINK"), kGrey, true,
                 tr("Controller \"%1\" is not connected: this is the last value known, not the "
                    "position now.")
                     .arg(axis.controller));
        return;
    }
    if (showMoveWithoutReadback(row, a))
        return;
    if (a.known == machine::PositionKnowledge::Estimated)
        text.prepend(QStringLiteral("\u2248"));
    row.value->setText(text);
    if (a.known == machine::PositionKnowledge::Unknown)
        setState(row, tr("UNKNOWN"), kRed, true,
                 tr("Not referenced since the last panic, reset or reconnect: the position is "
                    "counted from where the axis was, not from the machine origin."));
    else if (a.moving)
        setState(row, tr("MOVING"), kAmber, false, tr("Moving, as the controller reports."));
    else if (a.known == machine::PositionKnowledge::Estimated)
        setState(row, tr("ESTIMATED"), kAmber, false,
                 tr("Estimated by the host; the controller did not confirm it."));
    else
        setState(row, tr("REFERENCED"), kGreen, false,
                 tr("Known from the controller: read back or set by a reference run."));
}

void MachineDro::setState(const Row& row, const QString& word, const QString& style, bool dim,
                          const QString& tip)
{
    row.state->setText(word);
    row.state->setToolTip(tip);
    setStyleSheetIfChanged(
        row.state,
        QStringLiteral("QLabel { %1 border-radius: 3px; font-weight: bold; padding: 2px; }")
            .arg(style));
    setStyleSheetIfChanged(row.value,
                           QStringLiteral("QLabel { background: #101418; color: %1;"
                                          " border-radius: 4px; padding: 2px 8px; }")
                               .arg(dim ? QStringLiteral("#6b7780") : QStringLiteral("#7CFC9A")));
}

bool MachineDro::zeroAxis(const QString& axis)
{
    const machine::Machine* m = m_context->machine();
    const machine::MachineAxis* a = m ? m->description().axis(axis) : nullptr;
    if (!a)
        return false;
    QString refusal;
    // Unknown also while the controller's link is down (Machine::axisStatus).
    const machine::MachineAxisStatus status = m->axisStatus(*a);
    if (!m_offsets->zero(axis, status, &refusal)) {
        m_message->setText(refusal);
        m_refusedAxis = axis; // the refusal goes when its cause does (refresh)
        return false;
    }
    m_refusedAxis.clear();
    m_message->setText(tr("Work origin of %1 set at machine %2 %3.")
                           .arg(axis, format(*a, status.position), unitOf(*a)));
    return true;
}

void MachineDro::clearOffsets()
{
    m_offsets->clear();
    m_refusedAxis.clear();
    m_message->setText(tr("Work offsets cleared: machine positions are shown."));
}

QString MachineDro::messageText() const
{
    return m_message->text();
}

QString MachineDro::displayedValue(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->text() : QString();
}

QString MachineDro::unitText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->unit() : QString();
}

QString MachineDro::stateText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).state->text() : QString();
}

QString MachineDro::detailText(const QString& axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).detail->text() : QString();
}

} // namespace stepdeck::ui
