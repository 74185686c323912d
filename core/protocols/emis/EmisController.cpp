// Link, connect sequence, status polling and the normalised status of the SMC-IC4; the safety
// contract of the base. Motion, jog, parameters and operations are the pieces' (header).
#include "EmisController.h"
#include "EmisLogging.h"
#include "EmisModel.h"
#include "Logging.h"
#include "transport/Transport.h"

namespace stepdeck::emis {

EmisController::EmisController(Transport* transport, const ControllerOptions& options,
                               QObject* parent)
    : Controller(transport, options, parent), m_exchange(transport, this),
      m_tracker(*this, m_known, this, trackerHooks()),
      m_motion(*this, m_exchange, m_known, m_tracker, motionHooks()),
      m_jog(*this, m_exchange, m_known, m_tracker, m_motion),
      m_parameters(*this, m_exchange, m_known, m_tracker),
      m_operations(*this, m_exchange, m_known, m_tracker, m_motion, m_parameters)
{
    for (Axis axis : emisAxes())
        mutableStatus().axes.insert(axis, AxisStatus{});
    for (int i = 0; i < kOutputCount; ++i)
        mutableStatus().outputs << std::nullopt;
    EmisLink* link = &m_exchange.link();
    link->setDefaultTimeout(options.commandTimeoutMs);
    connect(link, &EmisLink::arrived, this, [this](Axis axis) { m_tracker.onArrived(axis); });
    // No answer in time: the board may be starting again after a reset (5.8).
    connect(link, &EmisLink::timedOut, this, [this] { m_tracker.suspectReset(); });
    connect(link, &EmisLink::stray, this, [this](const QString& what) {
        ++mutableStatus().resyncCount;
        qCInfo(lcEmis) << what;
    });
    connect(link, &EmisLink::traffic, this,
            [this](TrafficRecord::Direction dir, const QByteArray& bytes, bool poll) {
                recordTraffic(dir, bytes, poll);
            });
    m_userPollMs = options.pollIntervalMs;
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    m_poller.setInterval(m_userPollMs);
    connect(&m_poller, &StatusPoller::pollDue, this, &EmisController::onPollDue);
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        // The port works, the board is silent: the base keeps the port open and reports.
        loseLink(tr("the SMC-IC4 did not answer %1 input polls (@IG) in a row").arg(misses));
    });
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    if (transport) {
        connect(transport, &Transport::opened, this, &EmisController::onOpened);
        connect(transport, &Transport::failed, this,
                [this](const QString& reason) { handleTransportFailure(reason); });
    }
    syncStatus();
}

EmisController::~EmisController() = default;

// The jog chain runs on vector moves: it hears of its chunks from both.
EmisMotionTracker::Hooks EmisController::trackerHooks()
{
    EmisMotionTracker::Hooks hooks;
    hooks.chunkArrived = [this] { m_jog.onChunkArrived(); };
    hooks.chunkLost = [this](const QString& why) { m_jog.halt(why); };
    return hooks;
}

EmisMotion::Hooks EmisController::motionHooks()
{
    EmisMotion::Hooks hooks;
    hooks.jogging = [this](Axis axis) { return m_jog.rate(axis) != 0.0; };
    hooks.chunkSettled = [this](bool ok, const QString& why) { m_jog.onChunkSettled(ok, why); };
    return hooks;
}

Capabilities EmisController::capabilities() const
{
    return emis::capabilities();
}

ParameterSchema EmisController::schema() const
{
    return parameterSchema();
}

void EmisController::setPollInterval(int ms)
{
    m_userPollMs = qMax(1, ms);
    m_poller.setInterval(m_userPollMs);
}

// ---------------------------------------------------------------- delegated

void EmisController::readParameters(RequestId id, const QStringList& names)
{
    m_parameters.read(id, names);
}

void EmisController::writeParameters(RequestId id, const ParameterSet& values, bool verify)
{
    Q_UNUSED(verify) // the SMC-IC4 cannot read working values back
    m_parameters.write(id, values);
}

void EmisController::moveRelative(RequestId id, const AxisVector& steps)
{
    m_motion.moveRelative(id, steps);
}

void EmisController::moveAbsolute(RequestId id, const AxisVector& targets)
{
    m_motion.moveAbsolute(id, targets);
}

void EmisController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    m_motion.reference(id, directions);
}

void EmisController::sendRaw(RequestId id, const QByteArray& bytes)
{
    m_operations.sendRaw(id, bytes);
}

void EmisController::modelOperation(RequestId id, const QString& name, const QVariantMap& args)
{
    if (!m_operations.run(id, name, args))
        Controller::modelOperation(id, name, args);
}

QString EmisController::jogRefusal() const
{
    if (QString base = Controller::jogRefusal(); !base.isEmpty())
        return base;
    return m_jog.refusal();
}

// ---------------------------------------------------------------- link

void EmisController::openLink(RequestId id)
{
    if (linkState() == LinkState::Connected)
        return finishOk(id);
    if (!transport())
        return finishError(id, ErrorKind::LinkDown, tr("no transport"));
    if (m_openId)
        return finishError(id, ErrorKind::Refused, tr("already connecting"));
    m_openId = id;
    m_tracker.startSession();
    m_known.speeds.forgetBoard(); // an earlier session (or program) may have left any work speed
    changeLink(LinkState::Connecting);
    if (transport()->isOpen())
        onOpened();
    else
        transport()->open(lineSettings());
}

void EmisController::onOpened()
{
    if (!m_openId)
        return;
    m_exchange.link().reset();
    m_exchange.link().settle(kSettleMs);
    identify(1);
}

void EmisController::identify(int retries)
{
    // 9.1 identifies the board (once more after a timeout: a board just powered up may miss
    // the first command); 9.15 tells the stored values (tolerant: the manual shows no example
    // answer); 9.2 gives the inputs, so the first status is complete.
    m_exchange.request(
        encode::version(), EmisLink::Expect::Ack, [this, retries](const EmisLink::Result& r) {
            if (r.outcome == EmisLink::Outcome::Timeout && retries > 0 && m_openId)
                return identify(retries - 1);
            if (r.outcome != EmisLink::Outcome::Ok) {
                return finishOpen(r.outcome == EmisLink::Outcome::Timeout
                                      ? ErrorKind::Timeout
                                      : m_exchange.failureKind(r),
                                  tr("no answer from an SMC-IC4 to @V (115200 baud 8N1): %1")
                                      .arg(m_exchange.failureText(encode::version(), r)));
            }
            mutableStatus().deviceFirmware = parseVersion(r.text).value_or(QString());
            m_parameters.readStored(0, [this](const EmisLink::Result& stored) {
                if (stored.outcome != EmisLink::Outcome::Ok)
                    qCInfo(lcEmis) << "*PRSYS not understood; stored values unknown";
                m_exchange.request(encode::allInputs(), EmisLink::Expect::Ack,
                                   [this](const EmisLink::Result& in) {
                                       if (const auto levels = parseAllInputs(in.text))
                                           applyInputs(*levels);
                                       finishOpen(ErrorKind::None, {});
                                   });
            });
        });
}

void EmisController::finishOpen(ErrorKind kind, const QString& message)
{
    if (!m_openId)
        return; // closed or failed meanwhile: already finished
    const RequestId id = std::exchange(m_openId, 0);
    if (kind != ErrorKind::None) {
        if (transport())
            transport()->close();
        changeLink(LinkState::Disconnected, message);
        if (id)
            finishError(id, kind, message);
        return;
    }
    changeLink(LinkState::Connected);
    m_poller.start();
    publish();
    if (id)
        finishOk(id);
}

void EmisController::sendSafetyStop(std::function<void(bool acknowledged)> done)
{
    // No stop command (chapter 9): nothing to send. The jog chain ends here, so no further
    // chunk goes out; a chunk or move under way ends by itself when it arrives.
    m_jog.end();
    done(!motionMayBeRunning());
}

bool EmisController::motionMayBeRunning() const
{
    return m_jog.sending() || m_tracker.mayBeRunning(); // a chunk may be on its way
}

void EmisController::abortHostSide(ErrorKind kind, const QString& message)
{
    m_poller.stop();
    if (m_openId)
        finishError(std::exchange(m_openId, 0), kind, message);
    stopTrackingMotion(message);
    m_exchange.cancelAll(kind, message);   // every pending request finishes with kind and message
    m_exchange.link().setExclusive(false); // an input program being written ends here
    syncStatus();                          // the base publishes next: no stale jog estimate in it
}

void EmisController::stopTrackingMotion(const QString& reason)
{
    m_jog.abort();
    m_known.speeds.forgetBoard();
    m_tracker.stopTracking(reason);
}

// ---------------------------------------------------------------- requests

bool EmisController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected)
        return true;
    finishError(id, ErrorKind::LinkDown, tr("not connected"));
    return false;
}

void EmisController::failExchange(RequestId id, const QByteArray& bytes, const EmisLink::Result& r)
{
    finishError(id, m_exchange.failureKind(r), m_exchange.failureText(bytes, r));
}

// ---------------------------------------------------------------- status

void EmisController::onPollDue()
{
    EmisLink& link = m_exchange.link();
    if (linkState() != LinkState::Connected || !link.isIdle() || link.isExclusive())
        return; // commands first; an input program being written owns the line
    m_poller.pollStarted();
    EmisLink::Request r;
    r.bytes = encode::allInputs();
    r.poll = true;
    r.timeoutMs = qMin(options().commandTimeoutMs, 200);
    r.done = [this](const EmisLink::Result& res) {
        if (res.outcome == EmisLink::Outcome::Cancelled)
            return;
        const auto levels =
            res.outcome == EmisLink::Outcome::Ok ? parseAllInputs(res.text) : std::nullopt;
        if (levels)
            applyInputs(*levels);
        // A <BEL> is a refusal (read as "busy" while a motor moves), so the board is there:
        // only silence and garbage count towards link loss. The inputs keep their last levels.
        m_poller.pollFinished(levels || res.outcome == EmisLink::Outcome::Refused);
        // Already due (an interval shorter than the exchange): the next @IG leaves now, ahead
        // of this one's publication and an event-loop pass (issue 21, polls back to back).
        if (m_poller.isDue())
            onPollDue();
        if (levels)
            publish();
    };
    link.submit(std::move(r));
}

void EmisController::refreshStatus(RequestId id)
{
    if (!requireLink(id))
        return;
    m_exchange.request(
        encode::allInputs(), EmisLink::Expect::Ack, [this, id](const EmisLink::Result& r) {
            if (busyMoving(r)) {
                // The board is there and says a motor still moves: the status is the motion
                // the host tracks, the inputs keep their last levels (as for a poll).
                publish();
                return finishOk(id, QVariant::fromValue(status()));
            }
            if (r.outcome != EmisLink::Outcome::Ok)
                return failExchange(id, encode::allInputs(), r);
            const auto levels = parseAllInputs(r.text);
            if (!levels) {
                return finishError(id, ErrorKind::Protocol,
                                   tr("@IG answered '%1', not eight input levels (9.2)")
                                       .arg(QString::fromLatin1(r.text)));
            }
            applyInputs(*levels);
            publish();
            finishOk(id, QVariant::fromValue(status()));
        });
}

bool EmisController::busyMoving(const EmisLink::Result& r) const
{
    // Chapter 9 ends answers with <BEL> "abhängig vom gesendeten Befehl und Betriebszustand";
    // StepDeck reads it as an invalid value or a motor still moving (docs/cli.md). @IG (9.2)
    // carries no value, so while the host tracks a motion it is the board busy with that
    // motion, not a fault of the read. Without a tracked motion it stays a refusal: the host
    // could not say which motor moves.
    return r.outcome == EmisLink::Outcome::Refused && motionMayBeRunning();
}

void EmisController::applyInputs(const QList<bool>& levels)
{
    mutableStatus().inputs = levels;
    qint64 word = 0;
    for (int i = 0; i < levels.size(); ++i)
        word |= levels[i] ? (qint64(1) << i) : 0;
    mutableStatus().raw.insert(QStringLiteral("inputs"), word);
}

void EmisController::syncStatus()
{
    MachineStatus& s = mutableStatus();
    bool busy = false;
    const QMap<Axis, EmisMotionTracker::Track>& tracks = m_tracker.tracks();
    for (auto it = tracks.cbegin(); it != tracks.cend(); ++it) {
        const EmisMotionTracker::Track& t = it.value();
        AxisStatus& a = s.axes[it.key()];
        a.position = t.position;
        a.referenced = t.referenced && !t.lost;
        a.positionKnown = a.referenced;
        a.positionEstimated = t.lost;
        const bool running = t.awaiting && !t.overdue;
        a.moving = running && !t.jogChunk;
        a.jogging = (running && t.jogChunk) || m_jog.rate(it.key()) != 0.0;
        a.limitSwitch = false; // the SMC-IC4 has no limit switch inputs
        // 5.2.1: inputs 1-4 are the reference switches X, Y, Z, U; a normally open switch is
        // active at high level, a normally closed one at low level.
        const int index = axisNumber(it.key()) - 1; // IN1..IN4 (5.2.2)
        const bool level = s.inputs && index < s.inputs->size() && s.inputs->at(index);
        a.referenceSwitch = m_known.switchNc.value(it.key(), false) ? !level : level;
        busy = busy || running;
    }
    s.busy = busy;
    // The work speed every positioning move runs at (EmisWorkSpeeds), where the host knows it:
    // a program's G1 overwrites it, and puts it back before G0 (motion::MoveExecutor).
    ParameterValue work;
    for (auto it = tracks.cbegin(); it != tracks.cend(); ++it)
        if (const std::optional<qint64> speed = m_known.speeds.knownMoveSpeed(it.key()))
            work.perAxis.insert(it.key(), *speed);
    if (work.perAxis.isEmpty())
        s.knownParameters.remove(QStringLiteral("work-speed"));
    else
        s.knownParameters.insert(QStringLiteral("work-speed"), work);
    // Interpolation as written in this session (a program turns it on, motion::MoveExecutor).
    if (m_known.interpolation)
        s.knownParameters.insert(QStringLiteral("interpolation"),
                                 ParameterValue{QVariant(*m_known.interpolation), {}});
    else
        s.knownParameters.remove(QStringLiteral("interpolation"));
    // One supply feeds logic and motor drivers (manual 4): a board that answers has its
    // drivers powered; there is no enable command.
    s.driveOn = linkState() == LinkState::Connected;
}

void EmisController::publish()
{
    syncStatus();
    publishStatus();
}

void EmisController::changeLink(LinkState state, const QString& reason)
{
    if (state == LinkState::Connecting || state == LinkState::Lost)
        m_tracker.forgetReferences(); // unknown until referenced in the new session
    syncStatus(); // setLinkState() publishes: the base's jog estimate must not leak into it
    setLinkState(state, reason);
}

} // namespace stepdeck::emis
