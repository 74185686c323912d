// A calibration or closed-loop reference run in progress: watched on the drive ('$', 'C', 'I')
// until it is ready again, then its result read back (readings: NanotecClosedLoop.h).
#include "NanotecClosedLoopRun.h"
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include <QTimer>

namespace stepdeck::nanotec {

namespace cl = closedloop;

namespace {
constexpr int kMonitorMs = 100;
// The manual gives no duration for either run; past these the drive is stopped ('S').
constexpr int kCalibrationDeadlineMs = 180000;
constexpr int kReferenceDeadlineMs = 120000;
} // namespace

NanotecClosedLoopRun::NanotecClosedLoopRun(NanotecController* controller, NanotecClosedLoop& loop)
    : m_ctl(controller), m_loop(loop)
{}

QString NanotecClosedLoopRun::runName(Kind kind)
{
    return kind == Kind::Calibration ? tr("calibration run (!101)")
                                     : tr("closed-loop reference run (!8)");
}

const NanotecClosedLoopRun::Run* NanotecClosedLoopRun::find(Axis axis) const
{
    const auto it = m_runs.constFind(axis);
    return it == m_runs.cend() ? nullptr : &*it;
}

int NanotecClosedLoopRun::deadlineMs(Kind kind) const
{
    return kind == Kind::Calibration ? kCalibrationDeadlineMs : kReferenceDeadlineMs;
}

bool NanotecClosedLoopRun::current(Axis axis, quint64 generation) const
{
    const auto it = m_runs.constFind(axis);
    return it != m_runs.cend() && it->generation == generation;
}

QString NanotecClosedLoopRun::runDetail(Axis axis) const
{
    const auto it = m_runs.constFind(axis);
    if (it == m_runs.cend())
        return {};
    return tr("%1 running, %2 s")
        .arg(runName(it->kind))
        .arg(double(it->clock.elapsed()) / 1000.0, 0, 'f', 1);
}

void NanotecClosedLoopRun::begin(RequestId id, Axis axis, Kind kind, qint64 restoreMode)
{
    HostDrive& d = m_ctl->m_drives[axis];
    d.motionPending = true;                  // tracked motion: refusals, 'S' on stop, never idle
    d.referencing = kind == Kind::Reference; // its end references the axis (applyStatusWord)
    AxisStatus& a = m_ctl->mutableStatus().axes[axis];
    a.referenced = a.positionKnown = false; // the motor turns
    Run run;
    run.kind = kind;
    run.id = id;
    run.generation = ++m_generation;
    run.restoreMode = restoreMode;
    run.position = d.position;
    run.clock.start();
    m_runs.insert(axis, run);
    m_loop.memoryOf(axis, kind) = cl::kResultRunning;
    m_loop.m_memory[axis]
        .enabled.reset(); // what the drive does with closed loop meanwhile is its own
    m_ctl->m_sweep.updateStatus();
    m_ctl->publishStatus();
    // The first look right after 'A': a run that turns the motor is busy then.
    const quint64 generation = run.generation;
    QTimer::singleShot(0, &m_loop, [this, axis, generation] { monitor(axis, generation); });
}

void NanotecClosedLoopRun::monitor(Axis axis, quint64 generation)
{
    if (!current(axis, generation))
        return;
    if (m_ctl->isClosing() || m_ctl->isLosingLink()) {
        // The safety stop has the bus; abortHostSide() ends the run with the link's verdict.
        QTimer::singleShot(kMonitorMs, &m_loop,
                           [this, axis, generation] { monitor(axis, generation); });
        return;
    }
    auto word = std::make_shared<qint64>(0);
    auto store = [this, axis, generation](bool encoder) {
        return sink([this, axis, generation, encoder](qint64 v) {
            if (!current(axis, generation))
                return;
            if (encoder) {
                m_runs[axis].encoder = v;
            } else {
                m_runs[axis].position = v;
                m_ctl->m_drives[axis].position = v;
            }
        });
    };
    // What the drive shows of a run: busy while it turns, its position and encoder position.
    QList<Step> steps{m_ctl->m_exchange.exchange(axis, "$", sink([word](qint64 v) { *word = v; })),
                      tolerant(m_ctl->m_exchange.exchange(axis, "C", store(false))),
                      tolerant(m_ctl->m_exchange.exchange(axis, "I", store(true)))};
    runSteps(steps, [this, axis, generation, word](const Failure& f) {
        if (!current(axis, generation))
            return;
        if (f.kind == ErrorKind::Cancelled)
            return; // stop, panic or disconnect: abortAll() ends the run
        if (f.ok())
            m_ctl->m_sweep.applyStatusWord(m_ctl->m_drives[axis], *word);
        onMonitored(axis, generation, f.ok() ? *word : -1);
    });
}

void NanotecClosedLoopRun::onMonitored(Axis axis, quint64 generation, qint64 word)
{
    Run& run = m_runs[axis];
    if (word >= 0 && decodeStatus(word).ready)
        return readResult(axis, generation, decodeStatus(word).positionError);
    run.sawBusy = run.sawBusy || word >= 0;
    if (!m_ctl->m_drives[axis].responding) {
        // Letting go of a motion: its stop first (safety contract), answered or not.
        m_loop.memoryOf(axis, run.kind) = cl::kResultAborted;
        tolerant(m_ctl->m_exchange.exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 0))(
            [](const Failure&) {});
        m_ctl->markMotionUnconfirmed();
        return endRun(axis, ErrorKind::Timeout,
                      tr("%1 stopped answering during its %2; %3")
                          .arg(m_ctl->driveName(axis), runName(run.kind),
                               Controller::mayStillBeMovingText()));
    }
    if (run.clock.elapsed() > deadlineMs(run.kind)) {
        const QString text = tr("%1 of %2 did not end within %3 s; stopped ('S')")
                                 .arg(runName(run.kind), m_ctl->driveName(axis))
                                 .arg(deadlineMs(run.kind) / 1000);
        m_loop.memoryOf(axis, run.kind) = cl::kResultAborted;
        tolerant(m_ctl->m_exchange.exchange(axis, "S", {}, NanotecBus::Priority::Urgent, 2))(
            [](const Failure&) {});
        return endRun(axis, ErrorKind::Timeout, text);
    }
    m_ctl->m_sweep.updateStatus(); // the drive table's detail shows the time so far
    m_ctl->publishStatus();
    QTimer::singleShot(kMonitorMs, &m_loop,
                       [this, axis, generation] { monitor(axis, generation); });
}

void NanotecClosedLoopRun::readResult(Axis axis, quint64 generation, bool failed)
{
    m_runs[axis].ended = true;
    auto code = std::make_shared<qint64>(0);
    QList<Step> steps;
    if (failed) {
        steps << tolerant(m_ctl->m_parameters.readStep(
            axis, *findParam(QStringLiteral("last-error")), [code](qint64 v) { *code = v; },
            nullptr));
    }
    steps << tolerant(
        m_ctl->m_exchange.setting(axis, "!" + QByteArray::number(m_runs[axis].restoreMode)));
    steps << tolerant(m_ctl->m_exchange.exchange(
        axis, "C", sink([this, axis, generation](qint64 v) {
            if (current(axis, generation))
                m_runs[axis].position = m_ctl->m_drives[axis].position = v;
        })));
    steps << tolerant(
        m_ctl->m_exchange.exchange(axis, "I", sink([this, axis, generation](qint64 v) {
                                       if (current(axis, generation))
                                           m_runs[axis].encoder = v;
                                   })));
    runSteps(steps, [this, axis, generation, failed, code](const Failure&) {
        if (!current(axis, generation))
            return;
        const Run run = m_runs.value(axis);
        QVariantMap value{{cl::kAxis, axisName(axis)},
                          {cl::kDurationMs, run.clock.elapsed()},
                          {cl::kPosition, run.position}};
        if (run.encoder)
            value.insert(cl::kEncoderPosition, *run.encoder);
        // A calibration turns the motor for a while: a drive ready at the first look right
        // after 'A' did not run it (a firmware without mode 101?) -- not claimed as done.
        const bool unconfirmed = !failed && run.kind == Kind::Calibration && !run.sawBusy;
        m_loop.memoryOf(axis, run.kind) =
            failed || unconfirmed ? cl::kResultFailed : cl::kResultDone;
        if (unconfirmed) {
            return endRun(axis, ErrorKind::VerifyFailed,
                          tr("%1 was ready again at the first status read after 'A': that the "
                             "%2 ran is not confirmed")
                              .arg(m_ctl->driveName(axis), runName(run.kind)));
        }
        if (!failed)
            return endRun(axis, ErrorKind::None, {}, value);
        endRun(axis, ErrorKind::Nak, failureText(axis, run.kind, int(*code)));
    });
}

QString NanotecClosedLoopRun::failureText(Axis axis, Kind kind, int code) const
{
    const QString error = code > 0
                              ? tr("%1: %2").arg(errorCodeName(code), errorCodeDescription(code))
                              : tr("no entry in the error memory");
    const QString consequence =
        kind == Kind::Calibration
            ? tr("is the encoder connected? The drive is not calibrated")
            : tr("is the encoder connected? The axis is not referenced and closed loop cannot "
                 "be switched on");
    return tr("%1 of %2 failed: the drive reports a position error (%3); %4. Clear the error "
              "with reset-position-error (5.14) before the next run")
        .arg(runName(kind), m_ctl->driveName(axis), error, consequence);
}

void NanotecClosedLoopRun::endRun(Axis axis, ErrorKind kind, const QString& message,
                                  const QVariantMap& value)
{
    const auto it = m_runs.find(axis);
    if (it == m_runs.end())
        return;
    const Run run = *it;
    m_runs.erase(it);
    HostDrive& d = m_ctl->m_drives[axis];
    AxisStatus& a = m_ctl->mutableStatus().axes[axis];
    if (kind == ErrorKind::None || kind == ErrorKind::Nak)
        d.motionPending = false; // the drive said ready
    if (run.kind == Kind::Reference) {
        // 6.6 / our reading of 8.1: the reference run ends on the reference position.
        d.referencing = false;
        a.referenced = a.positionKnown = kind == ErrorKind::None;
    }
    m_ctl->m_sweep.updateStatus();
    m_ctl->publishStatus();
    if (kind == ErrorKind::None)
        m_ctl->finishOk(run.id, value);
    else
        m_ctl->finishError(run.id, kind, message);
}

void NanotecClosedLoopRun::abortAll(ErrorKind kind, const QString& why)
{
    for (const Axis axis : m_runs.keys()) {
        const Run& run = m_runs[axis];
        m_loop.memoryOf(axis, run.kind) = cl::kResultAborted;
        const QString consequence = run.kind == Kind::Calibration
                                        ? tr("the drive is not calibrated; run it again")
                                        : tr("the axis is not referenced");
        const QString text =
            run.ended ? tr("%1 of %2 ended, but its result was not read back (%3)")
                            .arg(runName(run.kind), m_ctl->driveName(axis), why)
                      : tr("%1 of %2 aborted (%3): %4")
                            .arg(runName(run.kind), m_ctl->driveName(axis), why, consequence);
        qCInfo(lcNanotec) << text;
        endRun(axis, kind, text);
    }
}

} // namespace stepdeck::nanotec
