// Link, connect sequence, status polling and the normalised status of the SMC-IC4.
#include "EmisController.h"
#include "EmisLogging.h"
#include "EmisModel.h"
#include "Logging.h"
#include "transport/Transport.h"

namespace stepdeck::emis {

EmisController::EmisController(Transport* transport, const ControllerOptions& options,
                               QObject* parent)
    : Controller(transport, options, parent)
{
    for (Axis axis : allAxes()) {
        m_tracks.insert(axis, Track{});
        mutableStatus().axes.insert(axis, AxisStatus{});
    }
    for (int i = 0; i < kOutputCount; ++i)
        mutableStatus().outputs << std::nullopt;
    m_link = new EmisLink(transport, this);
    m_link->setDefaultTimeout(options.commandTimeoutMs);
    connect(m_link, &EmisLink::arrived, this, &EmisController::onArrived);
    // No answer in time: the board may be starting again after a reset (5.8).
    connect(m_link, &EmisLink::timedOut, this, &EmisController::suspectReset);
    connect(m_link, &EmisLink::stray, this, [this](const QString& what) {
        ++mutableStatus().resyncCount;
        qCInfo(lcEmis) << what;
    });
    connect(m_link, &EmisLink::traffic, this,
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
    m_deadlineTimer.setSingleShot(true);
    connect(&m_deadlineTimer, &QTimer::timeout, this, &EmisController::checkDeadlines);
    m_clock.start();
    if (transport) {
        connect(transport, &Transport::opened, this, &EmisController::onOpened);
        connect(transport, &Transport::failed, this,
                [this](const QString& reason) { handleTransportFailure(reason); });
    }
    syncStatus();
}

EmisController::~EmisController() = default;

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
    for (Track& t : m_tracks) {
        // A new session: positions count from here, nothing referenced. An axis that may
        // still be moving stays unconfirmed until its arrival or a reference run proves it.
        const bool unconfirmed = t.unconfirmed;
        t = Track{};
        t.unconfirmed = unconfirmed;
    }
    m_speeds.forgetBoard(); // an earlier session (or program) may have left any work speed
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
    m_link->reset();
    m_link->settle(kSettleMs);
    identify(1);
}

void EmisController::identify(int retries)
{
    // 9.1 identifies the board (once more after a timeout: a board just powered up may miss
    // the first command); 9.15 tells the stored values (tolerant: the manual shows no example
    // answer); 9.2 gives the inputs, so the first status is complete.
    request(encode::version(), EmisLink::Expect::Ack, [this, retries](const EmisLink::Result& r) {
        if (r.outcome == EmisLink::Outcome::Timeout && retries > 0 && m_openId)
            return identify(retries - 1);
        if (r.outcome != EmisLink::Outcome::Ok) {
            return finishOpen(r.outcome == EmisLink::Outcome::Timeout ? ErrorKind::Timeout
                                                                      : failureKind(r),
                              tr("no answer from an SMC-IC4 to @V (115200 baud 8N1): %1")
                                  .arg(failureText(encode::version(), r)));
        }
        mutableStatus().deviceFirmware = parseVersion(r.text).value_or(QString());
        readStoredParameters(0, [this](const EmisLink::Result& stored) {
            if (stored.outcome != EmisLink::Outcome::Ok)
                qCInfo(lcEmis) << "*PRSYS not understood; stored values unknown";
            request(encode::allInputs(), EmisLink::Expect::Ack, [this](const EmisLink::Result& in) {
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
    m_jogRates.clear();
    haltJogImmediately();
    done(!motionMayBeRunning());
}

bool EmisController::motionMayBeRunning() const
{
    if (m_jogSending)
        return true; // a chunk may be on its way
    for (const Track& t : m_tracks) {
        if (t.awaiting || t.startPending || t.unconfirmed)
            return true;
    }
    return false;
}

void EmisController::abortHostSide(ErrorKind kind, const QString& message)
{
    m_poller.stop();
    if (m_openId)
        finishError(std::exchange(m_openId, 0), kind, message);
    stopTrackingMotion(message);
    m_abort = qMakePair(kind, message);
    m_link->cancelAll(); // every pending request finishes with kind and message
    m_abort.reset();
    m_programming = false;
    m_link->setExclusive(false);
    syncStatus(); // the base publishes next: no stale jog estimate in it
}

void EmisController::stopTrackingMotion(const QString& reason)
{
    haltJogImmediately();
    m_jogRates.clear();
    m_jogSending = false;
    m_speeds.forgetBoard();
    for (auto it = m_tracks.begin(); it != m_tracks.end(); ++it) {
        if (!it->awaiting)
            continue;
        it->awaiting = false;
        it->overdue = false;
        it->jogChunk = false;
        markLost(it.key());
        qCWarning(lcEmis) << "stopped tracking axis" << axisName(it.key())
                          << "while it moved:" << reason;
    }
    m_deadlineTimer.stop();
    updateMotionUnconfirmed();
}

// ---------------------------------------------------------------- requests

void EmisController::request(const QByteArray& bytes, EmisLink::Expect expect, Handler done,
                             int timeoutMs, int storedMotors, bool exclusive)
{
    EmisLink::Request r;
    r.bytes = bytes;
    r.expect = expect;
    r.timeoutMs = timeoutMs;
    r.storedMotors = storedMotors;
    r.exclusive = exclusive;
    r.done = std::move(done);
    m_link->submit(std::move(r));
}

bool EmisController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected)
        return true;
    finishError(id, ErrorKind::LinkDown, tr("not connected"));
    return false;
}

ErrorKind EmisController::failureKind(const EmisLink::Result& r) const
{
    if (m_abort && r.outcome == EmisLink::Outcome::Cancelled)
        return m_abort->first;
    switch (r.outcome) {
    case EmisLink::Outcome::Ok:
        return ErrorKind::None;
    case EmisLink::Outcome::Refused:
        return ErrorKind::Nak;
    case EmisLink::Outcome::Timeout:
        return ErrorKind::Timeout;
    case EmisLink::Outcome::Protocol:
        return ErrorKind::Protocol;
    case EmisLink::Outcome::Cancelled:
        return ErrorKind::Cancelled;
    }
    return ErrorKind::Protocol;
}

QString EmisController::failureText(const QByteArray& bytes, const EmisLink::Result& r) const
{
    if (m_abort && r.outcome == EmisLink::Outcome::Cancelled)
        return m_abort->second;
    const QString command = formatTraffic(bytes);
    switch (r.outcome) {
    case EmisLink::Outcome::Ok:
        return {};
    case EmisLink::Outcome::Refused:
        return tr("the SMC-IC4 refused '%1' (<BEL>: invalid value, or the motor is still "
                  "moving)")
            .arg(command);
    case EmisLink::Outcome::Timeout:
        return r.detail.isEmpty()
                   ? tr("no reply to '%1' in time").arg(command)
                   : tr("no complete reply to '%1' in time: %2").arg(command, r.detail);
    case EmisLink::Outcome::Protocol:
        return tr("unexpected reply to '%1': %2").arg(command, r.detail);
    case EmisLink::Outcome::Cancelled:
        return r.detail.isEmpty() ? tr("'%1' was cancelled (disconnect)").arg(command) : r.detail;
    }
    return {};
}

void EmisController::finishFailure(RequestId id, const QByteArray& bytes, const EmisLink::Result& r)
{
    finishError(id, failureKind(r), failureText(bytes, r));
}

// ---------------------------------------------------------------- status

void EmisController::onPollDue()
{
    if (linkState() != LinkState::Connected || !m_link->isIdle() || m_link->isExclusive())
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
        if (levels)
            publish();
    };
    m_link->submit(std::move(r));
}

void EmisController::refreshStatus(RequestId id)
{
    if (!requireLink(id))
        return;
    request(encode::allInputs(), EmisLink::Expect::Ack, [this, id](const EmisLink::Result& r) {
        if (r.outcome != EmisLink::Outcome::Ok)
            return finishFailure(id, encode::allInputs(), r);
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
    for (auto it = m_tracks.cbegin(); it != m_tracks.cend(); ++it) {
        const Track& t = it.value();
        AxisStatus& a = s.axes[it.key()];
        a.position = t.position;
        a.referenced = t.referenced && !t.lost;
        a.positionKnown = a.referenced;
        a.positionEstimated = t.lost;
        const bool running = t.awaiting && !t.overdue;
        a.moving = running && !t.jogChunk;
        a.jogging = (running && t.jogChunk) || m_jogRates.value(it.key(), 0.0) != 0.0;
        a.limitSwitch = false; // the SMC-IC4 has no limit switch inputs
        // 5.2.1: inputs 1-4 are the reference switches X, Y, Z, U; a normally open switch is
        // active at high level, a normally closed one at low level.
        const int index = int(it.key());
        const bool level = s.inputs && index < s.inputs->size() && s.inputs->at(index);
        a.referenceSwitch = m_known.switchNc.value(it.key(), false) ? !level : level;
        busy = busy || running;
    }
    s.busy = busy;
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
    if (state == LinkState::Connecting || state == LinkState::Lost) {
        for (Track& t : m_tracks)
            t.referenced = false; // unknown until referenced in the new session
    }
    syncStatus(); // setLinkState() publishes: the base's jog estimate must not leak into it
    setLinkState(state, reason);
}

} // namespace stepdeck::emis
