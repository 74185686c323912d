#include "ElabController.h"
#include "ElabCtlParameters.h"
#include "ElabModel.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QPointer>
#include <QTimer>
#include <cmath>

namespace stepdeck::elab {

namespace {
constexpr int kTemperatureEveryNthPoll = 10;
constexpr int kStartButtonEveryNthPoll = 20;
} // namespace

ElabController::ElabController(Transport* transport, const ControllerOptions& options,
                               QObject* parent)
    : Controller(transport, options, parent), m_queue(transport, this),
      m_line(m_queue, mutableStatus(), hooks()),
      m_jog(m_line, ElabCtlJog::Hooks{[this] { haltJogImmediately(); },
                                      [this](const QString& why) { Q_EMIT jogRefused(why); },
                                      [this] { return linkState() == LinkState::Connected; },
                                      [this](const QString& why) { stopUntracked(why); }})
{
    MachineStatus& s = mutableStatus();
    for (Axis a : ElabCtlStatusMapper::axes())
        s.axes.insert(a, AxisStatus{});
    s.drives = {DriveStatus{0, ElabCtlStatusMapper::axes(), true, {}, {}}};

    m_queue.setTimeoutMs(options.commandTimeoutMs);
    m_queue.setCharacterTimeUs(elab::lineSettings().characterTimeUs());
    m_userPollMs = options.pollIntervalMs;
    m_poller.setInterval(options.pollIntervalMs);
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    connect(&m_poller, &StatusPoller::pollDue, this, &ElabController::startPoll);
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        loseLink(tr("no reply to %1 status polls in a row").arg(misses));
    });
    connect(&m_queue, &ElabExchangeQueue::trafficOut, this, [this](const QByteArray& b, bool p) {
        recordTraffic(TrafficRecord::Direction::Out, b, p);
    });
    connect(&m_queue, &ElabExchangeQueue::trafficIn, this, [this](const QByteArray& b, bool p) {
        recordTraffic(TrafficRecord::Direction::In, b, p);
    });
    connect(&m_queue, &ElabExchangeQueue::resyncStarted, this, [this](const QString& why) {
        ++mutableStatus().resyncCount;
        Q_EMIT errorOccurred(tr("resynchronising with <SYN> after: %1").arg(why));
    });
    connect(&m_queue, &ElabExchangeQueue::resyncFinished, this, [this](bool ok, quint16 word) {
        if (ok) {
            m_line.setMachineWord(word);
            publishStatus();
        }
    });
    connect(&m_queue, &ElabExchangeQueue::flowControl, this,
            [this](bool resume) { m_ops.onFlowControl(resume); });
    if (transport) {
        connect(transport, &Transport::opened, this, &ElabController::onOpened);
        connect(transport, &Transport::failed, this,
                [this](const QString& reason) { handleTransportFailure(reason); });
    }
}

ElabController::~ElabController() = default;

Capabilities ElabController::capabilities() const
{
    return elab::capabilities();
}
ParameterSchema ElabController::schema() const
{
    return elab::parameterSchema();
}

ElabCtlHooks ElabController::hooks()
{
    ElabCtlHooks h;
    h.ok = [this](RequestId id, const QVariant& value) { finishOk(id, value); };
    h.fail = [this](RequestId id, ErrorKind kind, const QString& message) {
        const QStringList written = m_writeProgress.take(id);
        finishError(id, kind,
                    written.isEmpty()
                        ? message
                        : tr("%1; already written: %2").arg(message, written.join(", ")));
    };
    h.publish = [this] { publishStatus(); };
    h.statusRead = [this] {
        trackLimitSwitches(); // before the motion bookkeeping forgets the direction
        m_ops.onStatusRead();
        checkUntrackedMotion();
    };
    h.requireLink = [this](RequestId id) { return requireLink(id); };
    h.error = [this](const QString& message) { Q_EMIT errorOccurred(message); };
    h.streamChanged = [this] { applyPollInterval(); };
    return h;
}

bool ElabController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected && !isClosing() && !isLosingLink())
        return true;
    finishError(id, ErrorKind::LinkDown, tr("not connected (%1)").arg(linkStateName(linkState())));
    return false;
}

QString ElabController::jogRefusal() const
{
    const QString base = Controller::jogRefusal();
    if (!base.isEmpty())
        return base;
    if (status().setupIncomplete)
        return tr("jog refused: setup incomplete (tmInvSetup): %1")
            .arg(ElabCtlParameters::setupIncompleteHint());
    if (m_ops.streaming())
        return tr("jog refused: a feed stream is running");
    return {};
}

void ElabController::moveRelative(RequestId id, const AxisVector& steps)
{
    m_ops.moveRelative(id, steps);
}

void ElabController::feed(RequestId id, const AxisVector& steps)
{
    m_ops.feed(id, steps);
}

void ElabController::feedStream(RequestId id, const QVector<AxisVector>& steps)
{
    m_ops.feedStream(id, steps);
}

// The board takes one vector per tick of its feed rate (manual, SetFeedStepXYZ): a contour's
// path speed is right only when the feed speeds of X, Y and Z are its tick rate, written before
// (where the rule "below the start speed" is judged). Refused otherwise, nothing sent.
void ElabController::feedContour(RequestId id, std::shared_ptr<motion::ContourFeed> contour)
{
    if (contour) {
        const ParameterValue feed = m_written.value(QStringLiteral("feed-speed"));
        const double rate = contour->tickRate();
        if (rate > ElabCtlMotionOps::kContourMaxTickRate) {
            // Faster, the pairs would leave the status polls no room (issue 47 item 4).
            finishError(id, ErrorKind::Refused,
                        tr("refused: the contour runs at %1 ticks/s; beside the status polls "
                           "the line carries at most %2")
                            .arg(rate)
                            .arg(ElabCtlMotionOps::kContourMaxTickRate));
            return;
        }
        for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
            const QVariant v = feed.perAxis.value(a);
            if (!v.isValid() || std::fabs(v.toDouble() - rate) > 1e-9) {
                finishError(id, ErrorKind::Refused,
                            tr("refused: the contour runs at %1 ticks/s, but the board's feed "
                               "speed on %2 is %3: write %1 on X, Y and Z first")
                                .arg(rate)
                                .arg(axisName(a))
                                .arg(v.isValid() ? v.toString() : tr("not known")));
                return;
            }
        }
        // The contour counts in the board's steps from where the axes stand now; the soft
        // limits then hold for every tick (the check refuses a program beyond them first).
        // Its slots are the board's axes in their order (Capabilities::axes, ContourMoves),
        // which is the order of the wire's step byte (wireIndex: X 0, Y 1, Z 2).
        const motion::StepPosition from = contour->steps();
        const QList<Axis> axes = capabilities().axes;
        for (int slot = 0; slot < int(axes.size()); ++slot) {
            const Axis a = axes.at(slot);
            Q_ASSERT(wireIndex(a) == size_t(slot));
            const qint64 here = status().axes.value(a).position;
            if (contour->ticks() == 0 && from[size_t(slot)] != here) {
                finishError(id, ErrorKind::Refused,
                            tr("refused: the contour starts with %1 at %2 steps, but it stands "
                               "at %3")
                                .arg(axisName(a))
                                .arg(from[size_t(slot)])
                                .arg(here));
                return;
            }
            if (softLimits().isActive(a, status())) {
                const AxisSoftLimit l = softLimits().limit(a);
                contour->setStepLimits(slot, axisName(a), l.minimum, l.maximum);
            }
        }
        QPointer<ElabController> self(this);
        contour->setWakeUp([self] {
            QMetaObject::invokeMethod(
                self,
                [self] {
                    if (self)
                        self->m_ops.pumpStream();
                },
                Qt::QueuedConnection);
        });
    }
    m_ops.feedContour(id, std::move(contour));
}

void ElabController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    AxisVector dirs;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it)
        dirs.insert(it.key(), it.value());
    m_ops.reference(id, dirs);
}

void ElabController::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    m_ops.velocityMove(id, stepsPerS);
}

// ------------------------------------------------------------------ link

void ElabController::openLink(RequestId id)
{
    if (!transport()) {
        finishError(id, ErrorKind::LinkDown, tr("no transport"));
        return;
    }
    if (linkState() == LinkState::Connected) {
        finishOk(id);
        return;
    }
    if (m_openId != 0) {
        finishError(id, ErrorKind::Refused, tr("already connecting"));
        return;
    }
    m_openId = id;
    m_queue.restart();
    m_limitApproach.clear();
    setLinkState(LinkState::Connecting);
    LineSettings line = elab::lineSettings();
    line.resetLine = options().resetLine;
    transport()->open(line);
}

void ElabController::onOpened()
{
    if (m_openId == 0)
        return;
    // Start clean: a half-received command of an earlier session is finished off by a burst of
    // <SYN> (RequestSync), then the status words, temperature and start button are read.
    ElabExchange burst = ElabCtlLine::exchange(0, encode::requestSync(16), Expect::None);
    burst.droppable = false;
    m_queue.enqueue(burst);
    ElabCtlLine::StatusRead how;
    how.temperature = how.startButton = how.tolerant = true;
    m_line.readStatus(
        0, how,
        [this] {
            if (m_line.machineWord() & machine::InvSetup)
                forgetWritten(); // the board lost its setup (power cycle): nothing is known
            m_line.setHostPanic(false);
            setLinkState(LinkState::Connected);
            m_poller.start();
            finishOk(std::exchange(m_openId, 0));
        },
        [this](ErrorKind kind, const QString& why) {
            const RequestId id = std::exchange(m_openId, 0);
            if (id == 0)
                return;
            if (transport())
                transport()->close();
            setLinkState(LinkState::Disconnected, why);
            finishError(id, kind == ErrorKind::Timeout ? ErrorKind::Timeout : ErrorKind::LinkDown,
                        tr("the E-LAB board does not answer: %1").arg(why));
        });
}

void ElabController::cancelEverything(ErrorKind kind, const QString& message)
{
    m_line.newEpoch();
    m_ops.abortStream(kind, message);
    m_ops.clear();
    m_queue.failAll(kind, message);
    haltJogImmediately();
    m_jog.reset();
}

void ElabController::startPoll()
{
    // The poll goes behind queued commands; it never has more than one cycle in flight.
    if (linkState() != LinkState::Connected || !m_poller.isDue())
        return;
    if (m_ops.contourNeedsWire() && !pollDeferralSpent()) {
        // A contour's pairs first while its reserve at the board is short (a poll's round
        // trip would let the board run dry); the poll follows within milliseconds, and after
        // kMaxPollDeferralMs whatever the reserve: a moving machine's limit switches, positions
        // and panic are read at least 10 times a second (issue 47). Feed mode runs below the
        // start ramp, so a board that runs dry for a poll's round trip loses no step ("ohne
        // dass Schrittverluste auftreten").
        if (!m_pollDeferred) {
            m_pollDeferred = true;
            QTimer::singleShot(kDeferredPollMs, this, [this] {
                m_pollDeferred = false;
                startPoll();
            });
        }
        return;
    }
    m_pollDeferredSince.invalidate();
    m_poller.pollStarted();
    ++m_pollCount;
    ElabCtlLine::StatusRead how;
    how.poll = true;
    // During a motion only the status words go out (manual, during a feed: "keine weiteren
    // Kommandos"; a stream's timing suffers from every extra exchange).
    const bool quiet = motionMayBeRunning();
    how.temperature = !quiet && m_pollCount % kTemperatureEveryNthPoll == 1;
    how.startButton = !quiet && m_pollCount % kStartButtonEveryNthPoll == 0;
    m_line.readStatus(
        0, how,
        [this] {
            m_poller.pollFinished(true);
            // Already due (an interval shorter than a poll): the next poll's requests leave
            // now, ahead of this one's publication (ElabCtlLine::readStatus) and an event-loop
            // pass (issue 21, polls back to back). Queued commands still go first.
            startPoll();
        },
        [this](ErrorKind kind, const QString&) {
            // Cancelled by panic/stop is not a missed reply; timeouts and garbage are.
            m_poller.pollFinished(kind != ErrorKind::Timeout && kind != ErrorKind::Protocol);
        });
}

bool ElabController::pollDeferralSpent()
{
    if (!m_pollDeferredSince.isValid()) {
        m_pollDeferredSince.start();
        return false;
    }
    return m_pollDeferredSince.elapsed() >= kMaxPollDeferralMs;
}

void ElabController::setPollInterval(int ms)
{
    m_userPollMs = ms;
    applyPollInterval();
}

// While a stream runs the status is read at least kStreamPollsPerSecond times a second,
// whatever interval was asked for (issue 47: limit switches go unread otherwise); the
// interval asked for comes back when the stream ends.
void ElabController::applyPollInterval()
{
    const int streamMs = 1000 / ElabCtlMotionOps::kStreamPollsPerSecond;
    const int ms = m_ops.streaming() ? qMin(m_userPollMs, streamMs) : m_userPollMs;
    if (m_poller.interval() != ms)
        m_poller.setInterval(ms);
}

void ElabController::refreshStatus(RequestId id)
{
    if (!requireLink(id))
        return;
    ElabCtlLine::StatusRead how;
    how.temperature = how.startButton = true;
    m_line.readStatus(
        id, how, [this, id] { finishOk(id, QVariant::fromValue(status())); },
        [this, id](ErrorKind kind, const QString& why) { finishError(id, kind, why); });
}

void ElabController::sendRaw(RequestId id, const QByteArray& bytes)
{
    // Console: one command per send; the reply it expects follows from its control byte.
    if (!requireLink(id))
        return;
    if (bytes.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, tr("nothing to send"));
        return;
    }
    ElabExchange ex = ElabCtlLine::exchange(id, bytes, expectFor(bytes));
    ex.onReply = [this, id](const Reply& r) { finishOk(id, r.raw); };
    ex.onError = [this, id](ErrorKind kind, const QString& why) { finishError(id, kind, why); };
    m_queue.enqueue(std::move(ex));
}

// ------------------------------------------------------------------ parameters

void ElabController::writeParameters(RequestId id, const ParameterSet& values, bool verify)
{
    QList<ElabParameterWrite> plan;
    const QString invalid = ElabCtlParameters::plan(schema(), values, m_written, &plan);
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    if (const QString busy = hostMotionRefusal(); !busy.isEmpty()) {
        finishError(id, ErrorKind::Refused, busy);
        return;
    }
    const QString note =
        verify ? tr("written; the E-LAB board cannot read parameters back, nothing verified")
               : QString();
    // The board must stand still (RequestAxeState first), and the writes follow directly.
    m_line.preflight(id, ElabCtlStatusMapper::Rule::Standstill,
                     [this, plan, note](ElabCtlLine::Op op) { writeStep(op, plan, 0, note); });
}

QString ElabController::hostMotionRefusal() const
{
    if (jogActive() || m_jog.mayRun() || m_ops.motionTracked() || m_ops.streaming())
        return tr("refused: a motion is running; setup and outputs are written only at "
                  "standstill");
    return {};
}

void ElabController::writeStep(const ElabCtlLine::Op& op, const QList<ElabParameterWrite>& plan,
                               int index, const QString& note)
{
    // One setup command after the other; a NAK stops the sequence (the rest is not sent).
    if (index == plan.size()) {
        m_writeProgress.remove(op.id);
        finish(CommandResult{op.id, ErrorKind::None, note, {}});
        return;
    }
    if (m_line.stale(op))
        return;
    m_line.sendCommand(op, plan.at(index).frame, [this, op, plan, index, note] {
        rememberWritten(plan.at(index).name, plan.at(index).value);
        QStringList& done = m_writeProgress[op.id];
        if (!done.contains(plan.at(index).name))
            done << plan.at(index).name;
        writeStep(op, plan, index + 1, note);
    });
}

// Published before the request finishes, so whoever sees the result already sees the value.
void ElabController::rememberWritten(const QString& name, const ParameterValue& value)
{
    m_written.insert(name, value);
    mutableStatus().knownParameters = m_written;
    publishStatus();
}

void ElabController::forgetWritten()
{
    m_written.clear();
    mutableStatus().knownParameters.clear();
}

void ElabController::readParameters(RequestId id, const QStringList& names)
{
    const ParameterSchema s = schema();
    QStringList wanted = names;
    if (wanted.isEmpty()) {
        for (const ParameterSpec& spec : s.specs())
            wanted << spec.name;
    }
    ParameterSet out;
    QStringList unknown;
    for (const QString& name : wanted) {
        if (!s.find(name)) {
            finishError(id, ErrorKind::InvalidValue, tr("unknown parameter '%1'").arg(name));
            return;
        }
        if (m_written.contains(name))
            out.insert(name, m_written.value(name));
        else
            unknown << name;
    }
    if (!unknown.isEmpty()) {
        finishError(id, ErrorKind::Unsupported,
                    tr("E-LAB cannot read parameters back, and this session has not written: %1")
                        .arg(unknown.join(QStringLiteral(", "))));
        return;
    }
    finish(CommandResult{id, ErrorKind::None,
                         tr("E-LAB cannot read parameters back: these are the values this "
                            "session last wrote"),
                         QVariant::fromValue(out)});
}

// ------------------------------------------------------------------ auxiliaries

void ElabController::writeAuxiliary(RequestId id, const QString& name, const QVariant& value,
                                    const QByteArray& frame)
{
    if (!requireLink(id))
        return;
    if (const QString busy = hostMotionRefusal(); !busy.isEmpty()) {
        finishError(id, ErrorKind::Refused, busy);
        return;
    }
    m_line.preflight(id, ElabCtlStatusMapper::Rule::Standstill,
                     [this, id, name, value, frame](ElabCtlLine::Op op) {
                         m_line.sendCommand(op, frame, [this, id, name, value] {
                             rememberWritten(name, ParameterValue{value, {}});
                             finishOk(id);
                         });
                     });
}

void ElabController::setSpindle(RequestId id, int rpm)
{
    // SetSpindleRPM: "einen Wert zwischen 0 und 1000 in einem long Hex-Word".
    if (rpm < 0 || rpm > 1000) {
        finishError(id, ErrorKind::InvalidValue,
                    schema().validateScalar(*schema().find(QStringLiteral("spindle-rpm")), rpm));
        return;
    }
    writeAuxiliary(id, QStringLiteral("spindle-rpm"), qint64(rpm),
                   encode::spindleRpm(quint32(rpm)));
}

void ElabController::setCoolant(RequestId id, bool on)
{
    writeAuxiliary(id, QStringLiteral("coolant"), on, encode::coolant(on));
}

void ElabController::setDrivePower(RequestId id, int percent)
{
    // SetDrivePower: "einen Wert zwischen 0 und 100 in einem Hex-Byte".
    if (percent < 0 || percent > 100) {
        finishError(
            id, ErrorKind::InvalidValue,
            schema().validateScalar(*schema().find(QStringLiteral("drive-power")), percent));
        return;
    }
    writeAuxiliary(id, QStringLiteral("drive-power"), qint64(percent),
                   encode::drivePower(quint8(percent)));
}

} // namespace stepdeck::elab
