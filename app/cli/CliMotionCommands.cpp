// Motion and auxiliary commands. Refusals (limit switch, setup incomplete, not idle, position
// unknown) come from the adapter, which knows the manual's rules; the CLI only checks shapes.
#include "CliCommands.h"
#include "CliText.h"
#include "model/ModelOperations.h"
#include <QCoreApplication>
#include <QElapsedTimer>
#include <climits>
#include <limits>

namespace stepdeck::cli {

namespace {
// A positive number of milliseconds (--for MS, --timeout MS), decimal.
bool parseDuration(const QString& text, qint64* ms)
{
    return numbers::parseInteger(text, 1, std::numeric_limits<qint64>::max(), ms) ==
           NumberError::None;
}

Outcome connectAndRun(CliContext& c, const std::function<RequestId(ControllerSession&)>& start)
{
    Outcome result = c.connect();
    if (result.ok())
        result = c.session.run(start);
    return result;
}

// After a move: the positions it ended at (they only exist in this session on models that
// cannot read positions back), or the whole status as JSON.
Outcome reportPositions(CliContext& c)
{
    if (c.json())
        printJson(c.session.status().toJson(c.model->id));
    else
        printLine(CliText::tr("positions: %1").arg(formatPositions(c.session.status())));
    return Outcome::success();
}

// A failure while motion runs: the motion is stopped before the command returns, and the
// command returns once the device reports standstill (bounded), so that the axes are at rest
// when the CLI exits -- or the message says they may not be. Without the wait, a board still
// braking on its stop ramp was found moving by the next command.
Outcome stopThenFail(CliContext& c, const Outcome& failure)
{
    constexpr int kStopSettleMs = 5000;
    if (c.session.linkLost() || c.session.interrupted())
        return failure;
    const Outcome stopped = c.session.stopMotion();
    if (!stopped.ok())
        return Outcome::failure(failure.code,
                                CliText::tr("%1; %2").arg(failure.message, stopped.message));
    const Outcome still = c.session.waitUntilIdle(kStopSettleMs);
    if (!still.ok()) {
        return Outcome::failure(
            failure.code,
            CliText::tr("%1; after the stop: %2").arg(failure.message, still.message));
    }
    return Outcome::failure(failure.code, CliText::tr("%1; stopped").arg(failure.message));
}

using StartMove = std::function<RequestId(ControllerSession&, const AxisVector&)>;
using CheckValues = std::function<Outcome(const AxisVector&)>;
using StartRequest = std::function<RequestId(ControllerSession&)>;

// Models whose moves finish when the axes report arrival (laser-axis): the request itself is
// the wait, up to --arrival-timeout (exit 5 after it). An axis that reported its end switch
// instead of the target ends the command with exit 13.
Outcome positioningByArrival(CliContext& c, const StartRequest& start, bool noWait, int waitMs)
{
    Outcome result = c.connect();
    if (!result.ok())
        return result;
    if (noWait) {
        // The target only has to leave the process: the status read returns once the port took
        // every byte. A refusal (range, unknown position) has finished by then.
        RequestId moveId = 0;
        std::optional<CommandResult> early;
        const QMetaObject::Connection watch = QObject::connect(
            &c.session.session(), &ControllerSession::requestFinished, [&](const CommandResult& r) {
                if (r.id == moveId)
                    early = r;
            });
        result = c.session.run([&](ControllerSession& s) {
            moveId = start(s);
            return s.refreshStatus();
        });
        QObject::disconnect(watch);
        if (result.ok() && early && !early->ok())
            return Outcome::from(*early);
        return result;
    }
    const CommandResult done =
        c.session.call(start, waitMs > 0 ? waitMs : c.options.arrivalTimeoutMs + 5000);
    if (!done.ok())
        return Outcome::from(done);
    const QStringList endSwitch =
        done.value.toMap().value(QStringLiteral("endSwitch")).toStringList();
    if (!endSwitch.isEmpty()) {
        if (c.json())
            printJson(c.session.status().toJson(c.model->id));
        return Outcome::failure(
            ExitMotionAborted,
            CliText::tr("motion aborted: axis %1 stopped at its end switch (status 1) "
                        "before reaching its target; positions: %2")
                .arg(endSwitch.join(QStringLiteral(", ")), formatPositions(c.session.status())));
    }
    return reportPositions(c);
}

Outcome positioning(CliContext& c, const QStringList& args, const QString& command,
                    const StartMove& start, const CheckValues& check = {})
{
    const bool noWait = c.options.flag("no-wait");
    const std::optional<QString> timeoutText = c.options.value("timeout");
    qint64 timeoutMs = -1;
    if (timeoutText && !parseDuration(*timeoutText, &timeoutMs))
        return Outcome::usage(
            CliText::tr("%1 --timeout needs a positive number of milliseconds").arg(command));
    AxisVector steps;
    if (const Outcome parsed =
            parseAxisIntegers(command, args, c.axes(), &steps, c.options.axisNames);
        !parsed.ok())
        return parsed;
    if (check) {
        if (const Outcome checked = check(steps); !checked.ok())
            return checked;
    }
    if (c.capabilities().reportsArrival) {
        return positioningByArrival(
            c, [&](ControllerSession& s) { return start(s, steps); }, noWait,
            int(qMin<qint64>(timeoutMs, INT_MAX)));
    }
    Outcome result = connectAndRun(c, [&](ControllerSession& s) { return start(s, steps); });
    if (!result.ok() || noWait)
        return result;
    result = c.session.waitUntilIdle(int(qMin<qint64>(timeoutMs, INT_MAX)));
    if (result.code == ExitTimeout)
        return stopThenFail(c, result); // never left running past the caller's deadline
    if (result.ok() && c.session.status().motionUnconfirmed) {
        // A model without position read-back (EMIS) lost an arrival: nothing proves the stop.
        return Outcome::failure(
            ExitTimeout, CliText::tr("the device did not confirm that the move arrived: an axis "
                                     "may still be moving; positions are unknown until "
                                     "referenced"));
    }
    return result.ok() ? reportPositions(c) : result;
}

// The value of a spindle/power command, read and checked like the schema parameter of the
// same meaning (decimal; the message names the parameter and its range). A non-finite value
// is a usage error, anything else refused an invalid value.
Outcome readSchemaValue(const CliContext& c, const QString& parameter, const QString& text,
                        qint64* value)
{
    if (numbers::isNonFiniteWord(text))
        return Outcome::usage(CliText::tr("%1: '%2' is not a finite number").arg(parameter, text));
    const ParameterSpec* spec = c.model->schema.find(parameter);
    if (!spec) { // the adapter says whether the model can do it at all
        if (numbers::parseInteger(text, value) != NumberError::None)
            return Outcome::usage(CliText::tr("'%1' is not a decimal number").arg(text));
        return Outcome::success();
    }
    if (const QString e = c.model->schema.validateScalar(*spec, text); !e.isEmpty())
        return Outcome::failure(ExitInvalidValue, e);
    *value = c.model->schema.normalise(*spec, text).toLongLong();
    return Outcome::success();
}

Outcome noArguments(CliContext& c, const QStringList& args, const QString& command,
                    const std::function<RequestId(ControllerSession&)>& start)
{
    if (!args.isEmpty())
        return Outcome::usage(CliText::tr("%1 takes no arguments").arg(command));
    return connectAndRun(c, start);
}
} // namespace

Outcome cmdFeed(CliContext& c, QStringList args)
{
    const bool noWait = c.options.flag("no-wait");
    const auto oneAxisUnlessWaiting = [noWait](const AxisVector& steps) {
        int moving = 0;
        for (qint64 n : steps)
            moving += n != 0 ? 1 : 0;
        // A multi-axis feed is a host-driven <DC2> stream: it ends when this process does.
        if (noWait && moving > 1)
            return Outcome::usage(
                CliText::tr("feed --no-wait works for one axis only: a multi-axis "
                            "feed is streamed by the host while the CLI runs"));
        return Outcome::success();
    };
    return positioning(
        c, args, QStringLiteral("feed"),
        [](ControllerSession& s, const AxisVector& v) { return s.feed(v); }, oneAxisUnlessWaiting);
}

// The controller's own reference operations; a plain `home` runs on the machine
// (runsOnTheMachine(), CliMachineMotion.cpp).
Outcome cmdHome(CliContext& c, QStringList args)
{
    if (c.options.flag("closed-loop")) // the closed-loop reference run (manual 8.1)
        return homeClosedLoop(c, args);
    // --simultaneous: every named axis at once (EMIS "$Hxy,a", manual 9.9).
    const auto directionsValid = [](const AxisVector& directions) {
        for (auto it = directions.cbegin(); it != directions.cend(); ++it) {
            if (it.value() != 0 && it.value() != 1) {
                return Outcome::failure(
                    ExitInvalidValue,
                    CliText::tr("home --simultaneous: axis %1 takes 1 (reference) or "
                                "0 (leave out)")
                        .arg(axisName(it.key())));
            }
        }
        return Outcome::success();
    };
    const auto start = [](ControllerSession& s, const AxisVector& v) {
        QString axes;
        for (auto it = v.cbegin(); it != v.cend(); ++it)
            axes += it.value() != 0 ? axisName(it.key()) : QString();
        return s.modelOperation(operation::kReference, {{operation::arg::kAxes, axes},
                                                        {operation::arg::kSimultaneous, true}});
    };
    return positioning(c, args, QStringLiteral("home"), start, directionsValid);
}

// The velocity move runs until SIGINT/SIGTERM/SIGHUP or --for MS, then stops with a ramp.
// Any failure meanwhile stops it too before the command returns; and should this process end
// any other way, the adapter's close sends the stop (safety contract).
Outcome cmdVelocity(CliContext& c, QStringList args)
{
    const std::optional<QString> forText = c.options.value("for");
    qint64 forMs = -1;
    if (forText && !parseDuration(*forText, &forMs))
        return Outcome::usage(
            CliText::tr("velocity --for needs a positive number of milliseconds"));
    AxisVector rates;
    if (const Outcome parsed = parseAxisIntegers(QStringLiteral("velocity"), args, c.axes(), &rates,
                                                 c.options.axisNames);
        !parsed.ok())
        return parsed;
    Outcome result = connectAndRun(c, [&](ControllerSession& s) { return s.velocityMove(rates); });
    if (!result.ok())
        return c.session.linkLost() ? c.session.linkLostOutcome() : result;
    if (!c.json()) {
        printLine(forMs > 0
                      ? CliText::tr("velocity move running for %1 ms").arg(forMs)
                      : CliText::tr("velocity move running; Ctrl-C, SIGTERM or SIGHUP ends it with "
                                    "a ramped stop"));
    }
    QElapsedTimer clock;
    clock.start();
    while (forMs < 0 || clock.elapsed() < forMs) {
        if (!c.session.pause(CliSession::kIdlePollMs))
            break;
        if (c.session.linkLost())
            return c.session.linkLostOutcome();
        const MachineStatus& st = c.session.status();
        if (st.panic || !st.anyMoving()) // ended by itself: says why (limit, panic)
            return stopThenFail(c, c.session.waitUntilIdle());
    }
    c.session.takeInterrupt(); // the normal way to end it
    if (result = c.session.stopMotion(); !result.ok())
        return result;
    result = c.session.waitUntilIdle();
    return result.ok() ? reportPositions(c) : stopThenFail(c, result);
}

Outcome cmdReset(CliContext& c, QStringList args)
{
    return noArguments(c, args, QStringLiteral("reset"),
                       [](ControllerSession& s) { return s.reset(); });
}

Outcome cmdSpindle(CliContext& c, QStringList args)
{
    qint64 rpm = 0;
    if (args.size() != 1)
        return Outcome::usage(CliText::tr("spindle needs one RPM value, e.g. `spindle 500`"));
    if (const Outcome read = readSchemaValue(c, QStringLiteral("spindle-rpm"), args.first(), &rpm);
        !read.ok())
        return read;
    return connectAndRun(c, [&](ControllerSession& s) { return s.setSpindle(int(rpm)); });
}

Outcome cmdCoolant(CliContext& c, QStringList args)
{
    const QString word = args.size() == 1 ? args.first().toLower() : QString();
    if (word != QLatin1String("on") && word != QLatin1String("off"))
        return Outcome::usage(CliText::tr("coolant needs on or off"));
    const bool on = word == QLatin1String("on");
    return connectAndRun(c, [&](ControllerSession& s) { return s.setCoolant(on); });
}

Outcome cmdPower(CliContext& c, QStringList args)
{
    qint64 percent = 0;
    if (args.size() != 1)
        return Outcome::usage(CliText::tr("power needs one PERCENT value, e.g. `power 66`"));
    if (const Outcome read =
            readSchemaValue(c, QStringLiteral("drive-power"), args.first(), &percent);
        !read.ok())
        return read;
    return connectAndRun(c, [&](ControllerSession& s) { return s.setDrivePower(int(percent)); });
}

} // namespace stepdeck::cli
