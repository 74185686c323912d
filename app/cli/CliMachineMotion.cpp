// `stepdeck-cli --machine FILE move|jog|home|stop|panic`: the machine's axes by name, values in
// their units, through the core Machine (issue 19; docs/cli.md, "Machines").
#include "CliMachineMotion.h"
#include "CliMachineRun.h"
#include "CliSession.h"
#include "CliText.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include <QElapsedTimer>
#include <limits>
#include <optional>

namespace stepdeck::cli {

using machine::Machine;
using machine::MachineAxis;

using namespace machinemotion;

namespace {
constexpr int kJogRenewMs = 100;  // well inside every adapter's jog lease (300 ms)
constexpr int kRampDownMs = 5000; // bound for every jog to ramp down and stand

// A rate faster than the controller's ceiling (or the axis' maxJogSpeed) is refused, not
// limited: a typed rate is meant as given.
Outcome checkJogRates(const machine::MachineDescription& d, const QMap<QString, double>& rates)
{
    for (auto it = rates.cbegin(); it != rates.cend(); ++it) {
        const MachineAxis* a = d.axis(it.key());
        const ModelInfo* model = findModel(d.controller(a->controller)->modelId);
        double limit = model->capabilities.maxJogSpeed / a->stepsPerUnit;
        if (a->maxJogSpeed)
            limit = qMin(limit, *a->maxJogSpeed);
        if (qAbs(it.value()) > limit)
            return Outcome::failure(
                ExitInvalidValue,
                CliText::tr("jog: %1=%2 %3/s is out of range (allowed: -%4..%4 %3/s)")
                    .arg(it.key())
                    .arg(it.value())
                    .arg(machine::unitKey(a->unit))
                    .arg(limit));
    }
    return Outcome::success();
}

bool anyCommFault(CliMachineSession& m)
{
    for (const machine::MachineController& c : m.description().controllers) {
        if (m.machine().session(c.id)->status().commFault)
            return true;
    }
    return false;
}

// `home Z X` (the file's directions) or `home X=1 Z=-1` (this run's: 1 or -1 in the machine's
// sense, 0 leaves the axis out). A controller that picks the direction itself (EMIS 9.9)
// takes 1 only.
Outcome parseHomeAxes(const machine::MachineDescription& d, const QStringList& args,
                      QStringList* axes, QMap<QString, int>* directions)
{
    for (const QString& arg : args) {
        const int eq = arg.indexOf(QLatin1Char('='));
        const QString given = (eq < 0 ? arg : arg.left(eq)).trimmed();
        const MachineAxis* a = d.findAxis(given);
        if (!a)
            return Outcome::usage(CliText::tr("home: the machine has no axis %1 (home takes axis "
                                              "names, home Z X, or directions, home X=1 Z=-1)")
                                      .arg(given));
        const QString name = a->name;
        qint64 direction = 0;
        if (eq < 0) {
            *axes << name;
            continue;
        }
        const QString text = arg.mid(eq + 1);
        if (numbers::parseInteger(text, &direction) != NumberError::None)
            return Outcome::usage(
                CliText::tr("%1: %2: '%3' is not a decimal number").arg("home", name, text));
        if (direction < -1 || direction > 1)
            return Outcome::failure(ExitInvalidValue,
                                    CliText::tr("home: direction of axis %1 must be -1, 0 or 1, "
                                                "not %2")
                                        .arg(name)
                                        .arg(direction));
        const ModelInfo* model = findModel(d.controller(a->controller)->modelId);
        if (direction == -1 && !model->capabilities.referenceDirection)
            return Outcome::failure(ExitInvalidValue,
                                    CliText::tr("home: %1: %2 picks the reference direction "
                                                "itself: give %1=1")
                                        .arg(name, model->id));
        if (direction != 0)
            *axes << name;
        if (direction != 0 && model->capabilities.referenceDirection)
            directions->insert(name, int(direction));
    }
    if (!args.isEmpty() && axes->isEmpty())
        return Outcome::usage(CliText::tr("home: every axis given is left out (0)"));
    return Outcome::success();
}

// After the jog: every axis at rest, or the command stops every controller and says why.
Outcome rampDown(CliMachineSession& m)
{
    if (!m.jogRefusal().isEmpty() && !m.linkLost()) {
        // Refused because a drive stopped answering: a communication fault, judged like one.
        if (anyCommFault(m))
            m.waitFor([&m] { return m.linkLost(); }, CliSession::kJogRampDownMs);
        if (!m.linkLost())
            return stopThenFail(m, Outcome::failure(ExitRefused, m.jogRefusal()));
    }
    if (m.linkLost()) {
        m.stopAll(); // the machine told the others already; this waits for their answers
        return m.linkLostOutcome();
    }
    if (!m.waitFor([&m] { return everyAxisAtRest(m); }, kRampDownMs)) {
        const Outcome failed = stopThenFail(
            m,
            Outcome::failure(ExitTimeout,
                             CliText::tr("jog did not ramp down within %1 ms").arg(kRampDownMs)));
        return m.linkLost() ? m.linkLostOutcome() : failed;
    }
    return Outcome::success();
}

// The jog loop: renews the rates until forMs passed, a signal came, a controller refused or
// a link was lost.
Outcome runJog(CliMachineSession& m, const QMap<QString, double>& rates, qint64 forMs)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < forMs && !m.interrupted() && !m.linkLost() &&
           m.jogRefusal().isEmpty()) {
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
    return rampDown(m);
}
} // namespace

Outcome machineHome(CliMachineSession& m, const CliOptions& o)
{
    int timeoutMs = -1;
    if (Outcome bad = refuseOptions(o, QStringLiteral("home"), {"simultaneous", "closed-loop"});
        !bad.ok())
        return bad;
    QStringList axes;
    QMap<QString, int> directions;
    if (Outcome parsed = parseHomeAxes(m.description(), o.args, &axes, &directions); !parsed.ok())
        return parsed;
    if (!parseTimeout(o, &timeoutMs))
        return Outcome::usage(
            CliText::tr("home --timeout needs a positive number of milliseconds"));
    m.setReferenceDirections(directions);
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    QString refusal;
    const quint64 id = m.machine().reference(axes, &refusal);
    if (id == 0)
        return Outcome::failure(ExitRefused,
                                CliText::tr("home refused, nothing was sent: %1").arg(refusal));
    if (o.flag("no-wait"))
        return leaveRunning(m, &Machine::referenceFinished, id);
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
    if (Outcome parsed = parseUnits(QStringLiteral("jog"), o.args, m.description(), false, &rates);
        !parsed.ok())
        return parsed;
    if (Outcome allowed = checkJogRates(m.description(), rates); !allowed.ok())
        return allowed;
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
