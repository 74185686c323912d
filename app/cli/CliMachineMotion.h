#pragma once
// Shared by the machine motion commands (CliMachineMotion.cpp, CliMachineMove.cpp).
#include "CliMachineSession.h"
#include "CliOutput.h"
#include "CliText.h"
#include <optional>

namespace stepdeck::cli::machinemotion {

// "X=12.5 A=-90": machine axis names and decimal values; an axis counted in steps takes whole
// steps when `wholeSteps` (move). Usage errors (exit 2) name the command, a value out of range
// is exit 7; an axis the machine does not have lists the ones it has.
Outcome parseUnits(const QString& command, const QStringList& args,
                   const machine::MachineDescription& d, bool wholeSteps,
                   QMap<QString, double>* out);
// --timeout MS of move and home: -1 without it; false when it is not a positive number.
bool parseTimeout(const CliOptions& o, int* ms);
// Exit 2 for the options of `command` in `names` that only a single controller has.
Outcome refuseOptions(const CliOptions& o, const QString& command,
                      std::initializer_list<const char*> names);
// After a failure while motion may run: every controller stopped, and the command returns
// once every axis stands still (bounded), so nothing is left braking when the CLI exits.
Outcome stopThenFail(CliMachineSession& m, const Outcome& failure);
// Every axis of every controller at rest and no jog commanded.
bool everyAxisAtRest(CliMachineSession& m);

constexpr int kStatusWaitMs = 30000; // as CliSession::kRequestTimeoutMs

// The end of motion `id` (ok, message) once the machine's `signal` reported it, while it lives.
template <typename Signal> struct MotionEnd
{
    MotionEnd(CliMachineSession& m, Signal signal, quint64 id)
    {
        QObject::connect(&m.machine(), signal, &guard,
                         [this, id](quint64 finished, bool ok, const QString& message) {
                             if (finished == id)
                                 end.emplace(ok, message);
                         });
    }
    MotionEnd(const MotionEnd&) = delete;
    MotionEnd& operator=(const MotionEnd&) = delete;

    std::optional<std::pair<bool, QString>> end;
    QObject guard;
};

// Waits for the end of a move or reference run `id`, signalled by `signal`; past timeoutMs
// (< 0: none) every controller is stopped and the command exits 5 once the axes stand.
template <typename Signal>
Outcome waitMotion(CliMachineSession& m, Signal signal, quint64 id, int timeoutMs)
{
    const MotionEnd<Signal> watch(m, signal, id);
    const std::optional<std::pair<bool, QString>>& end = watch.end;
    m.waitFor([&] { return end.has_value() || m.linkLost(); }, timeoutMs);
    if (m.interrupted())
        return Outcome::failure(ExitInterrupted, CliText::tr("interrupted"));
    if (m.linkLost())
        return m.linkLostOutcome();
    if (!end)
        return stopThenFail(
            m, Outcome::failure(ExitTimeout,
                                CliText::tr("the motion did not end within %1 ms").arg(timeoutMs)));
    if (!end->first)
        return m.motionFailure(end->second);
    return Outcome::success();
}

// --no-wait: returns once every controller took its part of motion `id` (a status read
// queued behind it has finished), or with the part's refusal; the motion goes on.
template <typename Signal> Outcome leaveRunning(CliMachineSession& m, Signal signal, quint64 id)
{
    const MotionEnd<Signal> watch(m, signal, id);
    const std::optional<std::pair<bool, QString>>& end = watch.end;
    QMap<QString, RequestId> reads;
    for (const machine::MachineController& c : m.description().controllers)
        reads.insert(c.id, m.machine().session(c.id)->refreshStatus());
    const Outcome sent = m.waitAll(reads, kStatusWaitMs);
    if (end && !end->first)
        return m.motionFailure(end->second);
    return sent;
}

} // namespace stepdeck::cli::machinemotion
