// `stepdeck-cli --machine FILE move|jog|home|stop|panic`: the machine's axes by name, values in
// their units, through the core Machine (issue 19; docs/cli.md, "Machines").
#include "CliMachineRun.h"
#include "CliText.h"
#include "model/NumberParsing.h"
#include <QElapsedTimer>
#include <limits>
#include <optional>

namespace stepdeck::cli {

using machine::Machine;
using machine::MachineAxis;

namespace {
constexpr int kJogRenewMs = 100;  // well inside every adapter's jog lease (300 ms)
constexpr int kRampDownMs = 5000; // bound for every jog to ramp down and stand

// "X=12.5 A=-90": machine axis names and decimal values. Usage errors (exit 2) name the
// command; an axis the machine does not have lists the ones it has.
Outcome parseUnits(const QString& command, const QStringList& args,
                   const machine::MachineDescription& d, QMap<QString, double>* out)
{
    QStringList names;
    for (const MachineAxis& a : d.axes)
        names << a.name;
    if (args.isEmpty())
        return Outcome::usage(CliText::tr("%1 needs at least one AXIS=VALUE (axes: %2)")
                                  .arg(command, names.join(QStringLiteral(", "))));
    for (const QString& arg : args) {
        const int eq = arg.indexOf(QLatin1Char('='));
        const QString name = eq > 0 ? arg.left(eq).trimmed().toUpper() : QString();
        if (name.isEmpty())
            return Outcome::usage(
                CliText::tr("%1: expected AXIS=VALUE (e.g. X=12.5), got '%2'").arg(command, arg));
        if (!d.axis(name))
            return Outcome::usage(CliText::tr("%1: the machine has no axis %2 (its axes: %3)")
                                      .arg(command, name, names.join(QStringLiteral(", "))));
        if (out->contains(name))
            return Outcome::usage(CliText::tr("%1: axis %2 given twice").arg(command, name));
        double value = 0;
        const QString text = arg.mid(eq + 1);
        if (numbers::parseReal(text, &value) != NumberError::None)
            return Outcome::usage(CliText::tr("%1: %2: '%3' is not a finite decimal number")
                                      .arg(command, name, text));
        out->insert(name, value);
    }
    return Outcome::success();
}

// --timeout MS of move and home: -1 without it.
bool parseTimeout(const CliOptions& o, int* ms)
{
    *ms = -1;
    const std::optional<QString> text = o.value("timeout");
    return !text ||
           numbers::parseInt(*text, 1, std::numeric_limits<int>::max(), ms) == NumberError::None;
}

Outcome refuseSingleControllerOptions(const CliOptions& o, const QString& command)
{
    for (const char* name : {"no-wait", "simultaneous", "closed-loop"}) {
        if (o.flag(name))
            return Outcome::usage(CliText::tr("%1 --%2 is a single-controller option: use it with "
                                              "--controller ID, not on the machine")
                                      .arg(command, QLatin1String(name)));
    }
    return Outcome::success();
}

// Waits for the end of a move or reference run `id`, signalled by `signal`; past timeoutMs
// (< 0: none) every controller is stopped and the command exits 5.
template <typename Signal>
Outcome waitMotion(CliMachineSession& m, Signal signal, quint64 id, int timeoutMs)
{
    std::optional<std::pair<bool, QString>> end;
    QObject guard;
    QObject::connect(&m.machine(), signal, &guard,
                     [&end, id](quint64 finished, bool ok, const QString& message) {
                         if (finished == id)
                             end.emplace(ok, message);
                     });
    m.waitFor([&] { return end.has_value() || m.linkLost(); }, timeoutMs);
    if (m.interrupted())
        return Outcome::failure(ExitInterrupted, CliText::tr("interrupted"));
    if (m.linkLost())
        return m.linkLostOutcome();
    if (!end) {
        const Outcome stopped = m.stopAll();
        return Outcome::failure(
            ExitTimeout, CliText::tr("the motion did not end within %1 ms; %2")
                             .arg(timeoutMs)
                             .arg(stopped.ok() ? CliText::tr("it was stopped") : stopped.message));
    }
    if (!end->first)
        return m.motionFailure(end->second);
    return Outcome::success();
}

bool everyJogRampedDown(CliMachineSession& m)
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

// The jog loop: renews the rates until forMs passed, a signal came or a link was lost.
Outcome runJog(CliMachineSession& m, const QMap<QString, double>& rates, qint64 forMs)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < forMs && !m.interrupted() && !m.linkLost()) {
        QString refusal;
        if (!m.machine().jog(rates, &refusal)) {
            m.machine().endJog();
            return m.linkLost()
                       ? m.linkLostOutcome()
                       : Outcome::failure(ExitRefused, CliText::tr("jog: %1").arg(refusal));
        }
        m.pause(int(qMin<qint64>(kJogRenewMs, qMax<qint64>(1, forMs - clock.elapsed()))));
    }
    m.machine().endJog();
    if (m.interrupted())
        return Outcome::failure(ExitInterrupted, CliText::tr("interrupted"));
    if (m.linkLost()) {
        m.stopAll(); // the machine told the others already; this waits for their answers
        return m.linkLostOutcome();
    }
    if (!m.waitFor([&m] { return everyJogRampedDown(m); }, kRampDownMs)) {
        const Outcome stopped = m.stopAll();
        return m.linkLost() ? m.linkLostOutcome()
                            : Outcome::failure(ExitTimeout,
                                               CliText::tr("the jog did not ramp down within %1 "
                                                           "ms; %2")
                                                   .arg(kRampDownMs)
                                                   .arg(stopped.ok() ? CliText::tr("it was stopped")
                                                                     : stopped.message));
    }
    return Outcome::success();
}
} // namespace

Outcome machineMove(CliMachineSession& m, const CliOptions& o)
{
    QMap<QString, double> units;
    int timeoutMs = -1;
    if (Outcome bad = refuseSingleControllerOptions(o, QStringLiteral("move")); !bad.ok())
        return bad;
    if (Outcome parsed = parseUnits(QStringLiteral("move"), o.args, m.description(), &units);
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
    if (Outcome moved = waitMotion(m, &Machine::moveFinished, id, timeoutMs); !moved.ok())
        return moved;
    return printMachinePositions(m, o.json);
}

Outcome machineHome(CliMachineSession& m, const CliOptions& o)
{
    int timeoutMs = -1;
    if (Outcome bad = refuseSingleControllerOptions(o, QStringLiteral("home")); !bad.ok())
        return bad;
    QStringList axes;
    for (const QString& arg : o.args) {
        const QString name = arg.trimmed().toUpper();
        if (!m.description().axis(name))
            return Outcome::usage(
                CliText::tr("home: the machine has no axis %1 (home takes axis names: home Z X; "
                            "directions come from the machine file)")
                    .arg(arg));
        axes << name;
    }
    if (!parseTimeout(o, &timeoutMs))
        return Outcome::usage(
            CliText::tr("home --timeout needs a positive number of milliseconds"));
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    QString refusal;
    const quint64 id = m.machine().reference(axes, &refusal);
    if (id == 0)
        return Outcome::failure(ExitRefused,
                                CliText::tr("home refused, nothing was sent: %1").arg(refusal));
    if (Outcome done = waitMotion(m, &Machine::referenceFinished, id, timeoutMs); !done.ok())
        return done;
    return printMachinePositions(m, o.json);
}

Outcome machineJog(CliMachineSession& m, const CliOptions& o)
{
    const std::optional<QString> forText = o.value("for");
    int forMs = 0;
    if (!forText || numbers::parseInt(*forText, 1, std::numeric_limits<int>::max(), &forMs) !=
                        NumberError::None)
        return Outcome::usage(
            CliText::tr("jog needs --for MS (a positive number of milliseconds)"));
    QMap<QString, double> rates;
    if (Outcome parsed = parseUnits(QStringLiteral("jog"), o.args, m.description(), &rates);
        !parsed.ok())
        return parsed;
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    if (Outcome jogged = runJog(m, rates, forMs); !jogged.ok())
        return jogged;
    return printMachinePositions(m, o.json);
}

Outcome machineStop(CliMachineSession& m, const CliOptions& o)
{
    if (!o.args.isEmpty())
        return Outcome::usage(CliText::tr("stop takes no arguments"));
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    return m.stopAll();
}

Outcome machinePanic(CliMachineSession& m, const CliOptions& o)
{
    if (!o.args.isEmpty())
        return Outcome::usage(CliText::tr("panic takes no arguments"));
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    // Posted to every controller before any answer is awaited.
    const Outcome result = m.waitAll(m.machine().panic(), CliMachineSession::kStopWaitMs);
    if (result.ok() && !o.json)
        printLine(CliText::tr("emergency stop sent to every controller; positions are unknown "
                              "until referenced"));
    return result;
}

} // namespace stepdeck::cli
