// `stepdeck-cli move` on a machine (--machine FILE, or --model/--port as a machine of one
// controller): the axes by name, values in their units, through the core Machine (issue 19;
// docs/cli.md), and the helpers the other machine motion commands share.
#include "CliMachineMotion.h"
#include "CliMachineRun.h"
#include "model/NumberParsing.h"
#include <limits>

namespace stepdeck::cli {

using machine::Machine;
using machine::MachineAxis;

namespace machinemotion {

namespace {
constexpr int kStopSettleMs = 5000; // bound for the axes to stand after a stop

// One value: whole steps for an axis counted in steps when asked, else a decimal.
Outcome parseValue(const QString& command, const MachineAxis& axis, const QString& text,
                   bool wholeSteps, double* value)
{
    NumberError error = NumberError::None;
    if (wholeSteps && axis.unit == machine::AxisUnit::Step) {
        qint64 steps = 0;
        error = numbers::parseInteger(text, &steps);
        *value = double(steps);
    } else {
        error = numbers::parseReal(text, value);
    }
    switch (error) {
    case NumberError::None:
        return Outcome::success();
    case NumberError::Malformed:
        return Outcome::usage(
            CliText::tr("%1: %2: '%3' is not a decimal number").arg(command, axis.name, text));
    case NumberError::NonFinite:
        return Outcome::usage(
            CliText::tr("%1: %2: '%3' is not a finite number").arg(command, axis.name, text));
    case NumberError::OutOfRange:
        break;
    }
    return Outcome::failure(
        ExitInvalidValue,
        CliText::tr("%1: %2: '%3' is out of range").arg(command, axis.name, text));
}
} // namespace

namespace {
// A bus of 254 drives: the first names and how many there are, not a page of them.
QString axisList(const QStringList& names)
{
    constexpr int kShown = 12;
    if (names.size() <= kShown)
        return names.join(QStringLiteral(", "));
    return CliText::tr("%1, ... (%2 in all)")
        .arg(names.mid(0, kShown).join(QStringLiteral(", ")))
        .arg(names.size());
}
} // namespace

Outcome parseUnits(const QString& command, const QStringList& args,
                   const machine::MachineDescription& d, bool wholeSteps,
                   QMap<QString, double>* out)
{
    QStringList names;
    for (const MachineAxis& a : d.axes)
        names << a.name;
    if (args.isEmpty())
        return Outcome::usage(CliText::tr("%1 needs at least one AXIS=VALUE (axes: %2)")
                                  .arg(command, axisList(names)));
    for (const QString& arg : args) {
        const int eq = arg.indexOf(QLatin1Char('='));
        const QString given = eq > 0 ? arg.left(eq).trimmed() : QString();
        if (given.isEmpty())
            return Outcome::usage(
                CliText::tr("%1: expected AXIS=VALUE (e.g. X=12.5), got '%2'").arg(command, arg));
        const MachineAxis* axis = d.findAxis(given);
        if (!axis)
            return Outcome::usage(CliText::tr("%1: this machine has no axis %2 (its axes: %3)")
                                      .arg(command, given, axisList(names)));
        const QString name = axis->name;
        if (out->contains(name))
            return Outcome::usage(CliText::tr("%1: axis %2 given twice").arg(command, name));
        double value = 0;
        if (Outcome read = parseValue(command, *axis, arg.mid(eq + 1), wholeSteps, &value);
            !read.ok())
            return read;
        out->insert(name, value);
    }
    return Outcome::success();
}

bool parseTimeout(const CliOptions& o, int* ms)
{
    *ms = -1;
    const std::optional<QString> text = o.value("timeout");
    return !text ||
           numbers::parseInt(*text, 1, std::numeric_limits<int>::max(), ms) == NumberError::None;
}

Outcome refuseOptions(const CliOptions& o, const QString& command,
                      std::initializer_list<const char*> names)
{
    for (const char* name : names) {
        if (o.flag(name))
            return Outcome::usage(CliText::tr("%1 --%2 is a single-controller option: use it with "
                                              "--controller ID, not on the machine")
                                      .arg(command, QLatin1String(name)));
    }
    return Outcome::success();
}

bool everyAxisAtRest(CliMachineSession& m)
{
    for (const machine::MachineController& c : m.description().controllers) {
        const ControllerSession* s = m.machine().session(c.id);
        for (const AxisStatus& a : s->status().axes) {
            if (a.commandedVelocity != 0.0 || a.jogging || a.moving)
                return false;
        }
    }
    return true;
}

Outcome stopThenFail(CliMachineSession& m, const Outcome& failure)
{
    if (m.linkLost() || m.interrupted())
        return failure;
    const Outcome stopped = m.stopAll();
    if (!stopped.ok())
        return Outcome::failure(failure.code,
                                CliText::tr("%1; %2").arg(failure.message, stopped.message));
    if (!m.waitFor([&m] { return everyAxisAtRest(m); }, kStopSettleMs))
        return Outcome::failure(
            failure.code,
            CliText::tr("%1; after the stop: %2")
                .arg(failure.message,
                     CliText::tr("an axis still moves %1 ms after the stop").arg(kStopSettleMs)));
    return Outcome::failure(failure.code, CliText::tr("%1; stopped").arg(failure.message));
}

} // namespace machinemotion

namespace {
using namespace machinemotion;

bool motionUnconfirmed(CliMachineSession& m)
{
    for (const machine::MachineController& c : m.description().controllers) {
        if (m.machine().session(c.id)->status().motionUnconfirmed)
            return true;
    }
    return false;
}
} // namespace

Outcome machineMove(CliMachineSession& m, const CliOptions& o)
{
    QMap<QString, double> units;
    int timeoutMs = -1;
    if (Outcome parsed = parseUnits(QStringLiteral("move"), o.args, m.description(), true, &units);
        !parsed.ok())
        return parsed;
    if (!parseTimeout(o, &timeoutMs))
        return Outcome::usage(
            CliText::tr("move --timeout needs a positive number of milliseconds"));
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    QString refusal;
    const quint64 id = m.machine().move(units, o.flag("abs"), &refusal);
    if (id == 0)
        return Outcome::failure(ExitRefused,
                                CliText::tr("move refused, nothing was sent: %1").arg(refusal));
    if (o.flag("no-wait"))
        return leaveRunning(m, &Machine::moveFinished, id);
    if (Outcome moved = waitMotion(m, &Machine::moveFinished, id, timeoutMs); !moved.ok()) {
        if (moved.code == ExitMotionAborted) // where the axes ended
            moved.message =
                CliText::tr("%1; positions: %2").arg(moved.message, machinePositionsLine(m));
        return moved;
    }
    if (motionUnconfirmed(m)) // a model without read-back (EMIS) lost an arrival
        return Outcome::failure(
            ExitTimeout, CliText::tr("the device did not confirm that the move arrived: an axis "
                                     "may still be moving; positions are unknown until "
                                     "referenced"));
    return printMachinePositions(m, o.json);
}

} // namespace stepdeck::cli
