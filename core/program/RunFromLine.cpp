#include "RunFromLine.h"
#include "DrillCycle.h"
#include "ProgramCoordinates.h"
#include "ProgramReader.h"
#include <algorithm>
#include <vector>

namespace stepdeck::program {

namespace {
bool isCoolant(BlockKind k)
{
    return k == BlockKind::CoolantMist || k == BlockKind::CoolantFlood ||
           k == BlockKind::CoolantOff;
}

// A block's switch (a line of several actions gives a block each, ProgramLine).
void noteSwitches(const ProgramBlock& b, RunFromState* state)
{
    const BlockKind k = b.kind;
    if (isSpindleSwitch(k)) {
        state->spindle = k;
    } else if (isCoolant(k)) {
        state->coolant = k;
    } else if (k == BlockKind::ToolChange) {
        state->tool = b.number;
    } else if (k == BlockKind::End) {
        // LinuxCNC's M2: spindle and coolant off (the positions stay).
        state->spindle.reset();
        state->coolant.reset();
        state->tool = 0;
    }
}

bool movesAxes(BlockKind k)
{
    return k == BlockKind::Rapid || k == BlockKind::Feed || isArc(k) || k == BlockKind::DrillCycle;
}

// The axes a move names (a drilling cycle: X, Y and Z) are left where they stand.
void forget(const ProgramBlock& b, const machine::MachineDescription& d, AxisPositions* at)
{
    QStringList names = b.axes.keys();
    if (b.kind == BlockKind::DrillCycle)
        names = {QStringLiteral("X"), QStringLiteral("Y"), ProgramCoordinates::toolAxis()};
    for (const QString& name : std::as_const(names))
        if (const int i = d.axisIndex(name); i >= 0)
            (*at)[size_t(i)] = std::nullopt;
}

// A drilling cycle ends where DrillCycle leaves X, Y and Z. It plans from a known start: an axis
// the program has not put anywhere starts where it stands now (G98's initial level), and in G91,
// whose words count from that start, it stays unknown.
void followCycle(const ProgramBlock& b, const MachineFacts& facts,
                 const ProgramCoordinates& coordinates, AxisPositions* at)
{
    const machine::MachineDescription& d = facts.description;
    AxisPositions from = *at;
    for (qsizetype i = 0; i < d.axes.size(); ++i) {
        const auto here = facts.knownPositions.constFind(d.axes.at(i).name);
        if (!from[size_t(i)] && here != facts.knownPositions.cend())
            from[size_t(i)] = here.value();
    }
    const std::variant<DrillCycle, DrillCycle::Error> planned =
        DrillCycle::plan(b, d, from, coordinates.offsets(b, d));
    const DrillCycle* cycle = std::get_if<DrillCycle>(&planned);
    if (!cycle)
        return; // the check refuses it where it runs; before the start it leaves the axes
    for (const auto& [axis, value] : cycle->end())
        if (!b.relative || (*at)[size_t(axis)])
            (*at)[size_t(axis)] = value;
}

// Where block `b` leaves the axes, as the run's current point follows it (ProgramRunner::
// blockDone: ProgramCoordinates::advance, an arc's or a cycle's end). repeated: it runs more
// than once (a repeat's body), so a relative move ends where the count of passes puts it: its
// axes are left where they stand rather than guessed.
void follow(const ProgramBlock& b, const MachineFacts& facts, const ProgramCoordinates& coordinates,
            bool repeated, AxisPositions* at)
{
    const machine::MachineDescription& d = facts.description;
    if (repeated && b.relative && movesAxes(b.kind)) {
        forget(b, d, at);
        return;
    }
    if (isArc(b.kind)) {
        // An arc ends at its words (ArcPath::end is the programmed end exactly), as a G1 does.
        ProgramBlock end = b;
        end.kind = BlockKind::Feed;
        coordinates.advance(end, d, at);
    } else if (b.kind == BlockKind::DrillCycle) {
        followCycle(b, facts, coordinates, at);
    } else {
        coordinates.advance(b, d, at); // G0, G1, G28; the other blocks leave the axes
    }
}

// A rapid to machine positions (axis index, position in the axis' unit), named as written.
ProgramBlock rapidTo(const machine::MachineDescription& d,
                     const QList<std::pair<int, double>>& targets, int line)
{
    ProgramBlock b;
    b.line = line;
    b.kind = BlockKind::Rapid;
    b.machineCoordinates = true; // G53: the start point is in machine coordinates already
    QStringList words;
    for (const auto& [axis, value] : targets) {
        const QString& name = d.axes.at(axis).name;
        b.axes.insert(name, value); // inches false: the axis' own unit
        words << name + figure(value);
    }
    b.text = QStringLiteral("G53 G0 %1").arg(words.join(QLatin1Char(' ')));
    return b;
}

// "5.000 mm": a machine position as the Run-from-line dialog names where the axes stand.
QString positionText(const machine::MachineAxis& axis, double value)
{
    return QStringLiteral("%1 %2").arg(value, 0, 'f', 3).arg(machine::unitKey(axis.unit));
}
} // namespace

RunFromState RunFromState::before(ProgramReader& reader, int first, const MachineFacts& facts)
{
    RunFromState state;
    state.startPoint.assign(size_t(facts.description.axes.size()), std::nullopt);
    // The run's coordinates as it starts (ProgramRunner::resetRun): the G10s and G92s of the
    // lines before the start do not run, so neither the run nor its start point follows them.
    const ProgramCoordinates coordinates(facts.coordinateSystems, facts.activeSystem,
                                         facts.lengthTools());
    std::vector<qint64> passes; // of each repeat around the block (a start is outside them all)
    for (int i = 0; i < first; ++i) {
        const ProgramBlock* b = reader.at(i);
        if (!b)
            break;
        if (b->kind == BlockKind::RepeatStart) {
            passes.push_back(b->count);
            continue;
        }
        if (b->kind == BlockKind::RepeatEnd) {
            if (!passes.empty())
                passes.pop_back();
            continue;
        }
        if (std::any_of(passes.cbegin(), passes.cend(), [](qint64 n) { return n <= 0; }))
            continue; // a repeat of no passes: its blocks never run
        const bool repeated =
            std::any_of(passes.cbegin(), passes.cend(), [](qint64 n) { return n > 1; });
        noteSwitches(*b, &state);
        follow(*b, facts, coordinates, repeated, &state.startPoint);
        state.rpm = b->rpm;
    }
    if (const ProgramBlock* start = reader.at(first))
        state.rpm = start->rpm; // the S in effect where the run starts
    return state;
}

QList<ProgramBlock> RunFromState::switches(int line) const
{
    QList<ProgramBlock> out;
    if (spindle && *spindle != BlockKind::SpindleOff) {
        ProgramBlock b;
        b.line = line;
        b.kind = *spindle;
        b.rpm = rpm;
        b.text = QStringLiteral("%1 S%2").arg(blockWord(b.kind), figure(rpm));
        out << b;
    }
    if (coolant && *coolant != BlockKind::CoolantOff) {
        ProgramBlock b;
        b.line = line;
        b.kind = *coolant;
        b.text = blockWord(b.kind);
        out << b;
    }
    return out;
}

// gSender's and UGS's order: never towards the work with the tool low. Up first when the start
// is higher; else across at the height the tool has now, and down last.
QList<ProgramBlock> RunFromState::approach(const MachineFacts& facts, int line) const
{
    const machine::MachineDescription& d = facts.description;
    const QString zName = ProgramCoordinates::toolAxis();
    const int z = d.axisIndex(zName);
    std::optional<double> zTarget;
    QList<std::pair<int, double>> others;
    for (qsizetype i = 0; i < d.axes.size() && size_t(i) < startPoint.size(); ++i) {
        const std::optional<double>& to = startPoint[size_t(i)];
        if (!to)
            continue;
        const machine::MachineAxis& axis = d.axes.at(i);
        const auto here = facts.knownPositions.constFind(axis.name);
        if (here != facts.knownPositions.cend() && axis.toSteps(here.value()) == axis.toSteps(*to))
            continue; // there already, to the step
        if (i == z)
            zTarget = *to;
        else
            others << std::pair<int, double>(int(i), *to);
    }
    // An unknown Z counts as below the start: up first (the check refuses the move anyway).
    const auto zHere = facts.knownPositions.constFind(zName);
    const bool zUp = zTarget && (zHere == facts.knownPositions.cend() || *zTarget > zHere.value());
    QList<ProgramBlock> out;
    if (!zTarget) {
        if (!others.isEmpty())
            out << rapidTo(d, others, line);
        return out;
    }
    const ProgramBlock zMove = rapidTo(d, {std::pair<int, double>(z, *zTarget)}, line);
    if (zUp)
        out << zMove;
    if (!others.isEmpty())
        out << rapidTo(d, others, line);
    if (!zUp)
        out << zMove;
    return out;
}

QList<ProgramBlock> RunFromState::prelude(const MachineFacts& facts, int line) const
{
    return switches(line) + approach(facts, line);
}

QString RunFromState::text() const
{
    QStringList parts;
    if (spindle && *spindle != BlockKind::SpindleOff)
        parts << tr("spindle on at S%1 (%2)")
                     .arg(figure(rpm), *spindle == BlockKind::SpindleReverse
                                           ? QStringLiteral("M4")
                                           : QStringLiteral("M3"));
    if (coolant && *coolant != BlockKind::CoolantOff)
        parts << tr("coolant on (%1)")
                     .arg(*coolant == BlockKind::CoolantMist ? QStringLiteral("M7")
                                                             : QStringLiteral("M8"));
    if (tool > 0)
        parts << tr("tool %1 loaded").arg(tool);
    return parts.join(QStringLiteral(", "));
}

QString RunFromState::approachText(const MachineFacts& facts) const
{
    const machine::MachineDescription& d = facts.description;
    const QString z = ProgramCoordinates::toolAxis();
    const QList<ProgramBlock> moves = approach(facts, 0);
    QString text;
    for (const ProgramBlock& b : moves) {
        QString part;
        if (b.axes.size() == 1 && b.axes.contains(z)) {
            const double to = b.axes.value(z);
            const QString where = positionText(*d.axis(z), to);
            const auto here = facts.knownPositions.constFind(z);
            part = here == facts.knownPositions.cend() ? tr("%1 to %2").arg(z, where)
                   : to > here.value()                 ? tr("%1 up to %2").arg(z, where)
                                                       : tr("%1 down to %2").arg(z, where);
        } else {
            QStringList where; // in the machine's axis order, as the position text
            for (const machine::MachineAxis& a : d.axes)
                if (b.axes.contains(a.name))
                    where << QStringLiteral("%1 %2").arg(a.name,
                                                         positionText(a, b.axes.value(a.name)));
            part = where.join(QLatin1Char(' '));
        }
        text = text.isEmpty() ? part : tr("%1, then %2").arg(text, part);
    }
    return text.isEmpty() ? text : tr("%1 at rapid").arg(text);
}

} // namespace stepdeck::program
