#include "PositionPanel.h"
#include "common/ConnectionGate.h"
#include "common/Dialogs.h"
#include "common/ElidedLabel.h"
#include "common/IfChanged.h"
#include "common/LayoutItems.h"
#include "machine/MachineContext.h"
#include "machine/MachineDro.h"
#include "machine/MachineGoTo.h"
#include "machine/MachineWorkOffsets.h"
#include "position/DroValueLabel.h"
#include "position/GoToWidget.h"
#include "position/MoveEstimate.h"
#include "position/ReferenceRunner.h"
#include "position/SoftLimitsDialog.h"
#include "position/UnitsDialog.h"
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QToolButton>

namespace stepdeck::ui {

PositionPanel::PositionPanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_grid(new QGridLayout), m_moveTick(new QTimer(this)),
      m_gate(new ConnectionGate(context, this)), m_goTo(new GoToWidget(context, this))
{
    // The estimate advances between status reads.
    m_moveTick->setInterval(100);
    connect(m_moveTick, &QTimer::timeout, this, [this] { onStatus(m_context->status()); });
    // With a machine open (issue 19) its logical axes in units stand in place of the
    // selected controller's axes in steps (the controller's units, offsets, limits and go-to
    // stay out of the machine's read-out, which has work offsets of its own in the machine's
    // units).
    auto* outer = new QVBoxLayout(this);
    // The machine's work offsets, shared by its read-out and its go-to.
    MachineWorkOffsets* workOffsets = context->workOffsets();
    m_machineDro = new MachineDro(context, workOffsets, this);
    m_machineGoTo = new MachineGoTo(context, workOffsets, this);
    auto* controllerPart = new QWidget(this);
    outer->addWidget(m_machineDro);
    outer->addWidget(m_machineGoTo);
    outer->addWidget(controllerPart);
    outer->addStretch(1);
    auto* layout = new QVBoxLayout(controllerPart);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(m_grid);
    auto* buttons = new QHBoxLayout;
    auto* units = new QToolButton(this);
    units->setText(tr("Units\u2026"));
    units->setToolTip(tr("Steps per mm or per degree for each axis"));
    auto* clear = new QToolButton(this);
    clear->setText(tr("Clear work offsets"));
    clear->setToolTip(tr("Show machine positions again (work origin = machine origin)"));
    auto* limits = new QToolButton(this);
    limits->setText(tr("Soft limits\u2026"));
    limits->setToolTip(tr("Travel range per axis that jog and moves must not leave"));
    for (QToolButton* b : {units, clear, limits})
        b->setFocusPolicy(Qt::NoFocus);
    // Two lines: in German one line of three would widen the dock past a 1366x768 screen.
    buttons->addWidget(units);
    buttons->addWidget(limits);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    auto* offsets = new QHBoxLayout;
    offsets->addWidget(clear);
    offsets->addStretch(1);
    layout->addLayout(offsets);
    layout->addWidget(m_goTo);
    auto showPart = [this, controllerPart] {
        m_machineDro->setVisible(m_context->hasMachine());
        m_machineGoTo->setVisible(m_context->hasMachine());
        controllerPart->setVisible(!m_context->hasMachine());
    };
    connect(context, &MachineContext::machineChanged, this, showPart);
    showPart();
    connect(limits, &QToolButton::clicked, this, &PositionPanel::editSoftLimits);
    connect(context, &MachineContext::softLimitsChanged, this,
            [this] { onStatus(m_context->status()); });

    connect(units, &QToolButton::clicked, this, &PositionPanel::editUnits);
    connect(clear, &QToolButton::clicked, this, &PositionPanel::clearOffsets);
    connect(context, &MachineContext::modelChanged, this, &PositionPanel::rebuild);
    connect(context, &MachineContext::unitsChanged, this,
            [this] { onStatus(m_context->status()); });
    connect(context->session(), &ControllerSession::statusChanged, this, &PositionPanel::onStatus);
    connect(context->session(), &ControllerSession::linkStateChanged, this, [this] {
        m_moves.clear();
        m_idlePosition.clear();
        onStatus(m_context->status());
    });
    rebuild();
}

void PositionPanel::rebuild()
{
    deleteLayoutItems(m_grid); // with each row's detail line
    m_rows.clear();
    QFont big(QStringLiteral("monospace"));
    big.setStyleHint(QFont::Monospace);
    big.setPointSizeF(font().pointSizeF() * 2.6);
    big.setBold(true);
    QFont axisFont = font();
    axisFont.setPointSizeF(font().pointSizeF() * 2.2);
    axisFont.setBold(true);
    // The state badge is as wide as its longest word in this language: a new state never
    // widens the row (issue 16: MOVING pushed the badge and Zero off the dock).
    QFont badgeFont = font();
    badgeFont.setBold(true);
    int badgeWidth = 0;
    for (const QString& state : stateWords())
        badgeWidth = qMax(badgeWidth, QFontMetrics(badgeFont).horizontalAdvance(state) + 12);
    int r = 0;
    for (Axis axis : m_context->axes()) {
        Row row;
        auto* name = new QLabel(axisName(axis), this);
        name->setFont(axisFont);
        row.value = new DroValueLabel(this);
        row.value->setDigitFont(big);
        row.value->setStyleSheet(QStringLiteral("QLabel { background: #101418; color: #7CFC9A; "
                                                "border-radius: 4px; padding: 2px 8px; }"));
        row.steps = new ElidedLabel(this);
        row.steps->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.steps->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        row.state = new QLabel(this);
        row.state->setAlignment(Qt::AlignCenter);
        row.state->setFixedWidth(badgeWidth);
        row.limits = new ElidedLabel(this);
        row.limits->setStyleSheet(QStringLiteral("QLabel { color: palette(dark); }"));
        row.limits->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        auto* zero = new QToolButton(this);
        zero->setText(tr("Zero %1").arg(axisName(axis)));
        zero->setToolTip(
            tr("Set the work origin of %1 at the current position").arg(axisName(axis)));
        zero->setFocusPolicy(Qt::NoFocus);
        connect(zero, &QToolButton::clicked, this, [this, axis] { zeroAxis(axis); });
        m_gate->add(zero); // a zero needs the position now, not the last one known
        m_grid->addWidget(name, 2 * r, 0, 2, 1);
        m_grid->addWidget(row.value, 2 * r, 1);
        m_grid->addWidget(row.state, 2 * r, 2);
        // The line below spans the badge's column too: soft limits (when set), the machine
        // position or the target, and Zero. Its labels elide rather than widen the row.
        auto* detail = new QHBoxLayout;
        detail->setContentsMargins(0, 0, 0, 0);
        detail->addWidget(row.limits, 2);
        detail->addWidget(row.steps, 3);
        detail->addWidget(zero);
        m_grid->addLayout(detail, 2 * r + 1, 1, 1, 2);
        m_rows.insert(axis, row);
        ++r;
    }
    m_grid->setColumnStretch(1, 1);
    onStatus(m_context->status());
}

void PositionPanel::onStatus(const MachineStatus& status)
{
    bool anyMove = false;
    for (auto it = m_rows.cbegin(); it != m_rows.cend(); ++it) {
        showAxis(it.key(), it.value(), status.axes.value(it.key()));
        anyMove = anyMove || m_moves.value(it.key()).active;
    }
    if (anyMove && !m_moveTick->isActive())
        m_moveTick->start();
    else if (!anyMove)
        m_moveTick->stop();
}

std::optional<qint64> PositionPanel::estimate(Axis axis, const MoveTrack& move) const
{
    // The E-LAB ramp parameters by their schema names, as written or read in this session.
    const ParameterSet& known = m_context->knownParameters();
    auto value = [&](const char* name) {
        return known.value(QString::fromLatin1(name)).perAxis.value(axis).toDouble();
    };
    const MoveProfile profile{value("start-speed"), value("max-speed"), value("acceleration")};
    if (!profile.isValid())
        return std::nullopt;
    const qint64 distance = qAbs(move.to - move.from);
    const double done =
        MoveEstimate::travelled(double(distance), profile, move.clock.elapsed() / 1000.0);
    return move.from + (move.to >= move.from ? 1 : -1) * qint64(done);
}

void PositionPanel::setState(const Row& row, const QString& state, const QString& style, bool dim,
                             const QString& tip)
{
    row.state->setText(state);
    setStyleSheetIfChanged(
        row.state,
        QStringLiteral("QLabel { %1 border-radius: 3px; font-weight: bold; padding: 2px; }")
            .arg(style));
    setToolTipIfChanged(row.state, tip);
    setStyleSheetIfChanged(row.value,
                           QStringLiteral("QLabel { background: #101418; color: %1;"
                                          " border-radius: 4px; padding: 2px 8px; }")
                               .arg(dim ? QStringLiteral("#6b7780") : QStringLiteral("#7CFC9A")));
}

void PositionPanel::showAxis(Axis axis, const Row& row, const AxisStatus& a)
{
    static const QString red = QStringLiteral("background:#ffcdd2; color:#8e0000;");
    static const QString amber = QStringLiteral("background:#ffe082; color:#4e3400;");
    static const QString green = QStringLiteral("background:#c8e6c9; color:#1b5e20;");
    static const QString grey = QStringLiteral("background:#eceff1; color:#37474f;");
    const AxisUnits u = m_context->units(axis);
    auto format = [&](qint64 steps) {
        const double value = m_context->toUserUnits(axis, steps);
        return u.stepsPerUnit > 0 ? QString::number(value, 'f', 3) : QString::number(qint64(value));
    };
    // The large digits are work coordinates once a work zero is set: say so next to them;
    // the line below always gives the machine position.
    row.value->setReservedText(u.stepsPerUnit > 0 ? QStringLiteral("\u2248-00000.000")
                                                  : QStringLiteral("\u2248-0000000"));
    if (u.workOffset != 0) {
        row.value->setUnit(tr("%1 work").arg(m_context->unitName(axis)));
        setToolTipIfChanged(row.value,
                            tr("Work position: the machine position minus the work zero of %1 "
                               "(machine %2 %3)")
                                .arg(axisName(axis))
                                .arg(u.workOffset)
                                .arg(m_context->machineUnitName()));
    } else {
        row.value->setUnit(m_context->unitName(axis));
        setToolTipIfChanged(row.value,
                            tr("Machine position (no work zero set for %1)").arg(axisName(axis)));
    }
    const AxisSoftLimit limit = m_context->softLimits().limit(axis);
    row.limits->setVisible(limit.rangeSet); // without a range the line is the position's
    if (!limit.rangeSet) {
        row.limits->setText(tr("no soft limits"));
        setToolTipIfChanged(
            row.limits, tr("No travel range set for %1 (Soft limits\u2026)").arg(axisName(axis)));
    } else {
        const bool active =
            m_context->isConnected() && m_context->softLimits().isActive(axis, m_context->status());
        row.limits->setText(!limit.enabled ? tr("limits off")
                            : active ? tr("limits %1..%2").arg(limit.minimum).arg(limit.maximum)
                                     : tr("limits %1..%2 not applied: not referenced")
                                           .arg(limit.minimum)
                                           .arg(limit.maximum));
        setToolTipIfChanged(
            row.limits,
            active ? tr("Soft limits of %1 in machine %2: jog stops and moves are refused "
                        "there")
                         .arg(axisName(axis))
                         .arg(m_context->machineUnitName())
                   : tr("Soft limits of %1 in machine %2 apply only while the axis is "
                        "referenced: an unreferenced position says nothing about where the "
                        "machine is")
                         .arg(axisName(axis))
                         .arg(m_context->machineUnitName()));
    }
    MoveTrack& move = m_moves[axis];

    if (!m_context->isConnected()) {
        move.active = false;
        row.value->setText(format(a.position));
        row.steps->setText(
            tr("last known: machine %1 %2").arg(a.position).arg(m_context->machineUnitName()));
        setState(row, tr("NO LINK"), grey, true,
                 tr("The link is down: this is the last value before it ended, not the "
                    "position now."));
        return;
    }
    const bool readback = m_context->capabilities().positionReadback;
    if (m_referencing && m_referencing->currentAxes().contains(axis)) {
        // A reference run: the position is found when the axis reaches its switch; the
        // target the core counts until then ("moving to 0") means nothing.
        move.active = false;
        const qint64 shown = readback ? a.position : m_idlePosition.value(axis, a.position);
        row.value->setText(format(shown));
        row.steps->setText(readback ? tr("referencing\u2026 (machine %1 steps)").arg(shown)
                                    : tr("referencing\u2026"));
        setState(row, tr("REFERENCING"), amber, !readback,
                 readback ? tr("Reference run: read back from the controller; the position is "
                               "set when the axis reaches its reference switch.")
                          : tr("Reference run: the last position before it; the position is "
                               "set when the axis reaches its reference switch."));
        return;
    }
    if (a.moving && !readback) {
        // The core already counts the target; show where the axis probably is.
        if (!move.active) {
            move.active = true;
            move.from = m_idlePosition.value(axis, a.position);
            move.clock.start();
        }
        move.to = a.position;
        const std::optional<qint64> now = estimate(axis, move);
        // Without an estimate (ramp unknown, e.g. EMIS or after a reset) the digits say where
        // the axis is heading, dimmed: a lone "≈ …" read as a blank or broken read-out.
        row.value->setText(now ? QStringLiteral("\u2248") + format(*now)
                               : QStringLiteral("\u2192") + format(move.to));
        row.steps->setText(tr("moving to %1 (machine %2 %3)")
                               .arg(format(move.to))
                               .arg(move.to)
                               .arg(m_context->machineUnitName()));
        setState(row, tr("MOVING"), amber, !now,
                 now ? tr("Estimated from the ramp parameters; the controller reports no "
                          "position during a move. The target is shown below.")
                     : tr("The controller reports no position during a move and the ramp "
                          "parameters are not known in this session: the target is shown "
                          "(\u2192), not where the axis is now."));
        return;
    }
    move.active = false;
    if (!a.moving)
        m_idlePosition.insert(axis, a.position);
    QString text = format(a.position);
    if (a.positionEstimated && a.positionKnown)
        text.prepend(QStringLiteral("\u2248"));
    row.value->setText(text);
    row.steps->setText(tr("machine %1 %2").arg(a.position).arg(m_context->machineUnitName()));
    if (!a.positionKnown) {
        setState(row, tr("UNKNOWN"), red, true,
                 tr("Not referenced since the last panic, reset or reconnect: the position "
                    "is counted from where the axis was, not from the machine origin."));
    } else if (a.moving) {
        setState(row, tr("MOVING"), amber, false,
                 tr("Read back from the controller while moving."));
    } else if (a.positionEstimated) {
        setState(row, tr("ESTIMATED"), amber, false,
                 tr("Integrated from commanded jog rates; the controller did not confirm it."));
    } else if (a.referenced) {
        setState(row, tr("REFERENCED"), green, false, tr("Referenced and confirmed."));
    } else {
        setState(row, tr("SET"), amber, false,
                 tr("Known, but not from a reference run of this session."));
    }
}

void PositionPanel::setReferenceRunner(const ReferenceRunner* runner)
{
    m_referencing = runner;
    connect(runner, &ReferenceRunner::progress, this, [this] { onStatus(m_context->status()); });
    connect(runner, &ReferenceRunner::finished, this, [this] { onStatus(m_context->status()); });
    onStatus(m_context->status());
}

QStringList PositionPanel::stateWords()
{
    return {tr("NO LINK"),    tr("MOVING"), tr("UNKNOWN"),    tr("ESTIMATED"),
            tr("REFERENCED"), tr("SET"),    tr("REFERENCING")};
}

QString PositionPanel::displayedValue(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).value->text() : QString();
}

QString PositionPanel::stateText(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).state->text() : QString();
}

QString PositionPanel::detailText(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).steps->text() : QString();
}

void PositionPanel::zeroAxis(Axis axis)
{
    AxisUnits u = m_context->units(axis);
    u.workOffset = m_context->status().axes.value(axis).position;
    m_context->setUnits(axis, u);
}

void PositionPanel::clearOffsets()
{
    for (Axis axis : m_context->axes()) {
        AxisUnits u = m_context->units(axis);
        u.workOffset = 0;
        m_context->setUnits(axis, u);
    }
}

void PositionPanel::editSoftLimits()
{
    dialogs::showForPart(new SoftLimitsDialog(m_context, window()), this);
}

QString PositionPanel::limitsText(Axis axis) const
{
    return m_rows.contains(axis) ? m_rows.value(axis).limits->text() : QString();
}

void PositionPanel::editUnits()
{
    dialogs::showForPart(new UnitsDialog(m_context, window()), this);
}

} // namespace stepdeck::ui
