// The closed-loop workflow of drives with an encoder (Nanotec manual 8.1; the operations of
// model/ClosedLoop.h): `closed-loop [AXIS]` checks the motor data and the encoder, `calibrate`
// runs the calibration run, `home --closed-loop` the closed-loop reference run, and
// `closed-loop AXIS on|off` switches closed loop and reads it back. The adapter does the
// protocol work and the refusals; the CLI parses, waits, shows progress and the result.
#include "CliCommands.h"
#include "CliText.h"
#include "model/ClosedLoop.h"
#include "model/ModelOperations.h"
#include <QElapsedTimer>
#include <QJsonObject>

namespace stepdeck::cli {

namespace cl = closedloop;

namespace {
constexpr int kProgressMs = 1000;
// A safety net only: the adapter stops a run that takes longer than its own deadline (3 min).
constexpr int kRunLimitMs = 240000;

Outcome requireClosedLoop(const CliContext& c)
{
    if (c.capabilities().closedLoop)
        return Outcome::success();
    return Outcome::failure(
        ExitUnsupported, CliText::tr("%1 has no closed-loop workflow (calibration and closed-loop "
                                     "reference runs of encoder drives, e.g. nanotec)")
                             .arg(c.model->id));
}

// AXIS (or nothing on a one-axis machine), followed by at most one of `words`.
Outcome axisAndWord(const CliContext& c, const QString& command, QStringList args,
                    const QStringList& words, Axis* axis, QString* word)
{
    if (!args.isEmpty() && words.contains(args.last().toLower()))
        *word = args.takeLast().toLower();
    const QList<Axis> axes = c.axes();
    std::optional<Axis> chosen;
    if (args.size() == 1)
        chosen = c.options.axisNames.find(args.first()); // "feeder", or a default name
    else if (args.isEmpty() && axes.size() == 1)
        chosen = axes.first();
    if (args.size() > 1 || (args.isEmpty() && !chosen))
        return Outcome::usage(
            CliText::tr("%1 needs the axis of one drive, e.g. `%1 X`").arg(command));
    if (!chosen || !axes.contains(*chosen))
        return Outcome::usage(
            CliText::tr("%1: this machine has no axis %2").arg(command, args.first()));
    *axis = *chosen;
    return Outcome::success();
}

QString resultText(const QString& result)
{
    if (result == cl::kResultDone)
        return CliText::tr("done in this connection");
    if (result == cl::kResultFailed)
        return CliText::tr("FAILED in this connection");
    if (result == cl::kResultAborted)
        return CliText::tr("aborted in this connection");
    if (result == cl::kResultRunning)
        return CliText::tr("running");
    return CliText::tr("not run in this connection (the drive cannot report it)");
}

void printCheck(const QVariantMap& v)
{
    const QStringList problems = v.value(cl::kProblems).toStringList();
    printLine(CliText::tr("Motor pole pairs:  %1").arg(v.value(cl::kMotorPolePairs).toString()));
    printLine(CliText::tr("Encoder:           %1 increments per %2 revolution(s)")
                  .arg(v.value(cl::kEncoderIncrements).toString(),
                       v.value(cl::kEncoderRevolutions).toString()));
    printLine(CliText::tr("Step angle:        %1 deg").arg(v.value(cl::kStepAngle).toString()));
    printLine(
        CliText::tr("Encoder position:  %1 (position %2; the encoder is proven only when "
                    "the motor turns: the calibration run checks it)")
            .arg(v.value(cl::kEncoderPosition).toString(), v.value(cl::kPosition).toString()));
    printLine(CliText::tr("Closed loop:       %1 (read back)")
                  .arg(v.value(cl::kEnabled).toBool() ? CliText::tr("on") : CliText::tr("off")));
    printLine(
        CliText::tr("Calibration run:   %1").arg(resultText(v.value(cl::kCalibration).toString())));
    printLine(CliText::tr("Reference run:     %1")
                  .arg(resultText(v.value(cl::kReferenceRun).toString())));
    if (problems.isEmpty())
        printLine(CliText::tr("Motor data:        fit for closed loop (manual 8.6-8.8)"));
    for (const QString& p : problems)
        printLine(CliText::tr("PROBLEM:           %1").arg(p));
}

void printProgress(CliContext& c, Axis axis, const QString& what)
{
    const CommandResult r = c.session.call([&](ControllerSession& s) {
        return s.modelOperation(cl::kState, {{cl::kAxis, axisName(axis)}});
    });
    const QVariantMap v = r.value.toMap();
    if (!r.ok() || v.value(cl::kRun).toString() == cl::kRunNone)
        return;
    printLine(CliText::tr("%1: %2 s, position %3, encoder %4")
                  .arg(what)
                  .arg(v.value(cl::kElapsedMs).toDouble() / 1000.0, 0, 'f', 1)
                  .arg(v.value(cl::kPosition).toString(),
                       v.contains(cl::kEncoderPosition) ? v.value(cl::kEncoderPosition).toString()
                                                        : CliText::tr("not read yet")));
}

// Starts a run (calibration or closed-loop reference) and waits for its result, showing the
// drive's progress every second. A signal ends the wait: main() then sends the stop.
Outcome runWithProgress(CliContext& c, const QString& operation, Axis axis, const QVariantMap& args,
                        const QString& what, QVariantMap* value)
{
    std::optional<CommandResult> done;
    RequestId id = 0;
    const QMetaObject::Connection watch = QObject::connect(
        &c.session.session(), &ControllerSession::requestFinished, [&](const CommandResult& r) {
            if (r.id == id)
                done = r;
        });
    id = c.session.session().modelOperation(operation, args);
    QElapsedTimer clock;
    clock.start();
    while (!done && !c.session.linkLost() && clock.elapsed() < kRunLimitMs) {
        if (!c.session.waitFor([&] { return done || c.session.linkLost(); }, kProgressMs)) {
            if (c.session.interrupted())
                break;
            if (!c.json())
                printProgress(c, axis, what);
        }
    }
    if (!done && c.session.linkLost())
        c.session.waitFor([&] { return done.has_value(); }, 500); // its more precise message
    QObject::disconnect(watch);
    if (c.session.interrupted())
        return Outcome::failure(ExitInterrupted, CliText::tr("interrupted"));
    if (c.session.linkLost() && (!done || !done->ok()))
        return c.session.linkLostOutcome();
    if (!done)
        return Outcome::failure(ExitTimeout,
                                CliText::tr("no result within %1 s").arg(kRunLimitMs / 1000));
    *value = done->value.toMap();
    return Outcome::from(*done);
}

Outcome enableClosedLoop(CliContext& c, Axis axis, bool on)
{
    const CommandResult r = c.session.call([&](ControllerSession& s) {
        return s.modelOperation(cl::kEnable,
                                {{cl::kAxis, axisName(axis)}, {operation::arg::kOn, on}});
    });
    if (!r.ok())
        return Outcome::from(r);
    if (c.json())
        printJson(QJsonObject::fromVariantMap(r.value.toMap()));
    else
        printLine(CliText::tr("closed loop of axis %1: %2 (read back)")
                      .arg(axisName(axis), on ? CliText::tr("on") : CliText::tr("off")));
    return Outcome::success();
}

Outcome resetPositionError(CliContext& c, Axis axis)
{
    // 5.14 'D': the drive's own operation; the position becomes the encoder's.
    const Outcome r = c.session.run([&](ControllerSession& s) {
        return s.modelOperation(operation::kResetPositionError, {{cl::kAxis, axisName(axis)}});
    });
    if (r.ok() && !c.json())
        printLine(CliText::tr("position error of axis %1 cleared; its position is the encoder's "
                              "now (5.14)")
                      .arg(axisName(axis)));
    return r;
}
} // namespace

Outcome cmdClosedLoop(CliContext& c, QStringList args)
{
    Axis axis = Axis::X;
    QString word;
    Outcome result = axisAndWord(
        c, QStringLiteral("closed-loop"), args,
        {QStringLiteral("on"), QStringLiteral("off"), QStringLiteral("reset-error")}, &axis, &word);
    if (result.ok())
        result = requireClosedLoop(c);
    if (result.ok())
        result = c.connect();
    if (!result.ok())
        return result;
    if (word == QLatin1String("on") || word == QLatin1String("off"))
        return enableClosedLoop(c, axis, word == QLatin1String("on"));
    if (word == QLatin1String("reset-error"))
        return resetPositionError(c, axis);
    const CommandResult r = c.session.call([&](ControllerSession& s) {
        return s.modelOperation(cl::kCheck, {{cl::kAxis, axisName(axis)}});
    });
    if (!r.ok())
        return Outcome::from(r);
    if (c.json())
        printJson(QJsonObject::fromVariantMap(r.value.toMap()));
    else
        printCheck(r.value.toMap());
    return Outcome::success();
}

Outcome cmdCalibrate(CliContext& c, QStringList args)
{
    Axis axis = Axis::X;
    QString none;
    Outcome result = axisAndWord(c, QStringLiteral("calibrate"), args, {}, &axis, &none);
    if (result.ok())
        result = requireClosedLoop(c);
    if (result.ok())
        result = c.connect();
    if (!result.ok())
        return result;
    if (!c.json()) {
        printLine(CliText::tr("calibration run (!101) of axis %1: THE MOTOR TURNS. Manual 8.1: "
                              "needed for every newly connected motor; pole pairs and encoder "
                              "data must match the motor, or closed loop can speed it up beyond "
                              "its mechanical limits.")
                      .arg(axisName(axis)));
    }
    QVariantMap value;
    result = runWithProgress(c, cl::kCalibrate, axis, {{cl::kAxis, axisName(axis)}},
                             CliText::tr("calibrating axis %1").arg(axisName(axis)), &value);
    if (!result.ok())
        return result;
    if (c.json()) {
        printJson(QJsonObject::fromVariantMap(value));
        return Outcome::success();
    }
    printLine(CliText::tr("calibration of axis %1 done in %2 s; position %3, encoder %4 (unknown "
                          "until referenced: home --closed-loop %1=1)")
                  .arg(axisName(axis))
                  .arg(value.value(cl::kDurationMs).toDouble() / 1000.0, 0, 'f', 1)
                  .arg(value.value(cl::kPosition).toString(),
                       value.value(cl::kEncoderPosition).toString()));
    return Outcome::success();
}

Outcome homeClosedLoop(CliContext& c, const QStringList& args)
{
    AxisVector directions;
    Outcome result = parseAxisIntegers(QStringLiteral("home --closed-loop"), args, c.axes(),
                                       &directions, c.options.axisNames);
    for (auto it = directions.cbegin(); result.ok() && it != directions.cend(); ++it) {
        if (qAbs(it.value()) > 1)
            result = Outcome::failure(ExitInvalidValue,
                                      CliText::tr("home --closed-loop: direction of axis %1 must "
                                                  "be -1, 0 or 1, not %2")
                                          .arg(axisName(it.key()))
                                          .arg(it.value()));
    }
    if (result.ok())
        result = requireClosedLoop(c);
    if (result.ok())
        result = c.connect();
    // The drives one after the other: each run is watched until its drive is ready.
    for (auto it = directions.cbegin(); result.ok() && it != directions.cend(); ++it) {
        if (it.value() == 0)
            continue;
        QVariantMap value;
        result = runWithProgress(
            c, cl::kReference, it.key(),
            {{cl::kAxis, axisName(it.key())}, {operation::arg::kDirection, int(it.value())}},
            CliText::tr("closed-loop reference run of axis %1").arg(axisName(it.key())), &value);
    }
    if (!result.ok())
        return result;
    if (Outcome polled = c.session.refresh(); !polled.ok())
        return polled;
    if (c.json())
        printJson(c.session.status().toJson(c.model->id));
    else
        printLine(CliText::tr("positions: %1").arg(formatPositions(c.session.status())));
    return Outcome::success();
}

} // namespace stepdeck::cli
