// Link, drive initialisation, status sweeps and the normalised status of a Nanotec bus.
#include "NanotecController.h"
#include "Logging.h"
#include "NanotecModel.h"
#include "transport/Transport.h"
#include <QtMath>

namespace stepdeck::nanotec {

NanotecController::NanotecController(Transport* transport, const ControllerOptions& options,
                                     QObject* parent)
    : Controller(transport, options, parent)
{
    const QMap<Axis, int> map =
        options.axisAddresses.isEmpty() ? defaultAxisAddresses() : options.axisAddresses;
    QList<int> seen;
    for (auto it = map.cbegin(); it != map.cend(); ++it) {
        if (!isValidAddress(it.value()) || seen.contains(it.value())) {
            m_configError = tr("axis map: address %1 of axis %2 is invalid or used twice "
                               "(allowed 1..254, one drive per axis)")
                                .arg(it.value())
                                .arg(axisName(it.key()));
        }
        seen << it.value();
        Drive d;
        d.axis = it.key();
        d.address = it.value();
        m_drives.insert(it.key(), d);
        mutableStatus().axes.insert(it.key(), AxisStatus{});
    }
    m_bus = new NanotecBus(transport, this);
    m_bus->setDefaultTimeout(options.commandTimeoutMs);
    connect(m_bus, &NanotecBus::unsolicited, this, &NanotecController::onUnsolicited);
    connect(m_bus, &NanotecBus::garbage, this, [this] { ++mutableStatus().resyncCount; });
    connect(m_bus, &NanotecBus::traffic, this,
            [this](TrafficRecord::Direction dir, const QByteArray& bytes, bool poll) {
                recordTraffic(dir, bytes, poll);
            });
    m_userPollMs = options.pollIntervalMs;
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    connect(&m_poller, &StatusPoller::pollDue, this, &NanotecController::onPollDue);
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        onLinkLost(tr("no drive answered %1 status sweeps in a row").arg(misses));
    });
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    if (transport) {
        connect(transport, &Transport::opened, this, &NanotecController::onTransportOpened);
        connect(transport, &Transport::failed, this, &NanotecController::onTransportFailed);
    }
    updateStatus();
}

NanotecController::~NanotecController() = default;

Capabilities NanotecController::capabilities() const
{
    return nanotec::capabilities(m_drives.keys());
}

ParameterSchema NanotecController::schema() const
{
    return parameterSchema();
}

QString NanotecController::driveName(Axis axis) const
{
    return tr("drive %1 (axis %2)").arg(m_drives.value(axis).address).arg(axisName(axis));
}

int NanotecController::sweepBudgetMs() const
{
    // Per drive and sweep: "#1$\r" + "001$17\r" + "#1C\r" + "001C-1234567\r" = 27 characters,
    // plus a quarter of "#1ZY\r" + "001ZY196671\r" for the inputs: about 31 characters.
    int drives = 0;
    for (const Drive& d : m_drives)
        drives += d.responding ? 1 : 0;
    const double us = qMax(1, drives) * 31 * lineSettings().characterTimeUs();
    return int(qCeil(us / 1000.0));
}

int NanotecController::pollTimeoutMs() const
{
    // A status reply is under 15 characters (8 ms at 19200 baud): a short timeout keeps a
    // silent drive from stalling the sweep of the others.
    return qMin(options().commandTimeoutMs, 150);
}

void NanotecController::setPollInterval(int ms)
{
    m_userPollMs = qMax(1, ms);
    m_poller.setInterval(qMax(m_userPollMs, sweepBudgetMs()));
}

// ---------------------------------------------------------------- link

void NanotecController::openLink(RequestId id)
{
    if (!m_configError.isEmpty())
        return finishError(id, ErrorKind::InvalidValue, m_configError);
    if (linkState() == LinkState::Connected)
        return finishOk(id);
    if (!transport())
        return finishError(id, ErrorKind::LinkDown, tr("no transport"));
    if (m_pendingOpen)
        return finishError(id, ErrorKind::Refused, tr("already connecting"));
    m_pendingOpen = id;
    setLinkState(LinkState::Connecting);
    if (transport()->isOpen())
        onTransportOpened();
    else
        transport()->open(lineSettings());
}

void NanotecController::closeLink()
{
    m_poller.stop();
    m_bus->cancelAll();
    for (Drive& d : m_drives) {
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.motionPending = false;
    }
    if (transport() && transport()->isOpen())
        transport()->close();
    if (m_pendingOpen) {
        finishError(m_pendingOpen, ErrorKind::Cancelled, tr("connection closed"));
        m_pendingOpen = 0;
    }
    setLinkState(LinkState::Disconnected);
}

void NanotecController::onTransportOpened()
{
    m_bus->resetDecoder();
    if (m_pendingOpen)
        initialiseDrives();
    else if (m_pendingScan)
        runPendingScan();
}

void NanotecController::onTransportFailed(const QString& reason)
{
    m_poller.stop();
    m_bus->cancelAll();
    if (m_pendingOpen) {
        finishError(m_pendingOpen, ErrorKind::LinkDown, reason);
        m_pendingOpen = 0;
    }
    if (m_pendingScan) {
        finishError(m_pendingScan->id, ErrorKind::LinkDown, reason);
        m_pendingScan.reset();
    }
    if (linkState() == LinkState::Connected || linkState() == LinkState::Connecting) {
        setLinkState(LinkState::Lost, reason);
        Q_EMIT errorOccurred(tr("link lost: %1").arg(reason));
    }
}

void NanotecController::onLinkLost(const QString& reason)
{
    m_poller.stop();
    m_bus->cancelAll();
    // The port itself works, only the drives are silent: a '#*S' costs nothing and stops any
    // drive that still listens. The port stays open; openLink() starts over on it.
    NanotecBus::Request stopAll;
    stopAll.address = kBroadcast;
    stopAll.body = "S";
    stopAll.priority = NanotecBus::Priority::Urgent;
    m_bus->submit(stopAll);
    for (Drive& d : m_drives) {
        d.jog = Jog::Idle;
        d.jogBusy = false;
        d.velocityMove = false;
        d.motionPending = false;
    }
    setLinkState(LinkState::Lost, reason);
    Q_EMIT errorOccurred(tr("link lost: %1").arg(reason));
}

void NanotecController::initialiseDrives()
{
    m_initialising = true;
    QList<Step> perDrive;
    for (Axis axis : m_drives.keys()) {
        // Firmware first (5.22): a drive that does not answer it is flagged and skipped; the
        // rest only fills caches, so a drive that answers but refuses one of them stays.
        Step identify = exchange(
            axis, "v",
            [this, axis](const Reply& r) {
                m_drives[axis].firmware = r.firmware.text;
                return Failure{};
            },
            NanotecBus::Priority::Command, 1);
        QList<Step> rest{
            // Auto status (5.31): a 'j' at the end of every move saves polling for it.
            tolerant(exchange(axis, "J1")),
            tolerant(exchange(
                axis, "Ze", sink([this, axis](qint64 v) { m_drives[axis].limitSwitchType = v; }))),
            tolerant(exchange(axis, "Zu",
                              sink([this, axis](qint64 v) { m_drives[axis].minFrequency = v; }))),
            tolerant(exchange(axis, "Zo",
                              sink([this, axis](qint64 v) { m_drives[axis].maxFrequency = v; }))),
            tolerant(
                exchange(axis, "Zb", sink([this, axis](qint64 v) { m_drives[axis].ramp = v; }))),
            tolerant(exchange(
                axis, "$", sink([this, axis](qint64 v) { applyStatusWord(m_drives[axis], v); }))),
            tolerant(
                exchange(axis, "C", sink([this, axis](qint64 v) { m_drives[axis].position = v; }))),
        };
        perDrive << [this, axis, identify, rest](const Done& done) {
            identify([this, axis, rest, done](const Failure& f) {
                Drive& d = m_drives[axis];
                d.responding = f.kind != ErrorKind::Timeout && f.kind != ErrorKind::Cancelled;
                d.misses = d.responding ? 0 : m_poller.missLimit();
                if (!f.ok())
                    qCWarning(lcNanotec) << "initialising" << driveName(axis) << ":" << f.message;
                if (!d.responding)
                    return done({});
                runSteps(rest, [done](const Failure&) { done({}); });
            });
        };
    }
    runSteps(perDrive, [this](const Failure&) {
        m_initialising = false;
        QStringList silent;
        for (const Drive& d : m_drives) {
            if (!d.responding)
                silent << QString::number(d.address);
        }
        const RequestId id = m_pendingOpen;
        m_pendingOpen = 0;
        if (silent.size() == m_drives.size()) {
            const QString why = tr("no drive answered at address %1 (19200 baud 8N1)")
                                    .arg(silent.join(QStringLiteral(", ")));
            if (transport())
                transport()->close();
            setLinkState(LinkState::Disconnected, why);
            finishError(id, ErrorKind::Timeout, why);
            return;
        }
        setLinkState(LinkState::Connected);
        setPollInterval(m_userPollMs);
        m_poller.start();
        updateStatus();
        publishStatus();
        if (!silent.isEmpty())
            Q_EMIT errorOccurred(tr("no answer from drive %1; the other drives work")
                                     .arg(silent.join(QStringLiteral(", "))));
        finishOk(id);
    });
}

// ---------------------------------------------------------------- status

void NanotecController::onPollDue()
{
    if (linkState() != LinkState::Connected || m_initialising || m_poller.isPollInFlight())
        return;
    if (m_bus->hasQueued(NanotecBus::Priority::Urgent) ||
        m_bus->hasQueued(NanotecBus::Priority::Command))
        return; // commands first; the poller reminds us after an interval
    ++m_sweeps;
    QList<Axis> axes;
    bool anyResponding = false;
    for (const Drive& d : m_drives)
        anyResponding = anyResponding || d.responding;
    for (const Drive& d : m_drives) {
        // A silent drive costs a full timeout: ask it only every tenth sweep.
        if (d.responding || !anyResponding || m_sweeps % 10 == 0)
            axes << d.axis;
    }
    m_poller.pollStarted();
    pollDrive(axes, m_sweeps % 4 == 1, std::make_shared<bool>(false));
}

void NanotecController::pollDrive(QList<Axis> remaining, bool withInputs,
                                  std::shared_ptr<bool> answered)
{
    if (remaining.isEmpty()) {
        m_poller.pollFinished(*answered);
        updateStatus();
        publishStatus();
        return;
    }
    const Axis axis = remaining.takeFirst();
    auto request = [this, axis](const QByteArray& body, NanotecBus::Handler done) {
        NanotecBus::Request r;
        r.address = m_drives[axis].address;
        r.body = body;
        r.priority = NanotecBus::Priority::Poll;
        r.timeoutMs = pollTimeoutMs();
        r.poll = true;
        r.done = std::move(done);
        m_bus->submit(r);
    };
    auto next = [this, remaining, withInputs, answered] {
        pollDrive(remaining, withInputs, answered);
    };
    using O = NanotecBus::Outcome;
    request("$", [=](O o, const Reply& r) {
        if (o == O::Cancelled)
            return m_poller.pollFinished(true); // stop/panic/disconnect took the bus
        Drive& d = m_drives[axis];
        noteAnswer(d, o != O::Timeout);
        if (o != O::Ok || !r.value)
            return next();
        *answered = true;
        applyStatusWord(d, *r.value);
        request("C", [=](O o2, const Reply& r2) {
            if (o2 == O::Cancelled)
                return m_poller.pollFinished(true);
            if (o2 == O::Ok && r2.value)
                m_drives[axis].position = *r2.value;
            if (!withInputs)
                return next();
            request("ZY", [=](O o3, const Reply& r3) {
                if (o3 == O::Cancelled)
                    return m_poller.pollFinished(true);
                if (o3 == O::Ok && r3.value)
                    m_drives[axis].inputs = *r3.value;
                next();
            });
        });
    });
}

void NanotecController::noteAnswer(Drive& d, bool answered)
{
    if (answered) {
        d.misses = 0;
        if (!d.responding) {
            d.responding = true;
            qCInfo(lcNanotec) << driveName(d.axis) << "answers again";
            setPollInterval(m_userPollMs);
        }
        return;
    }
    ++d.misses;
    if (d.responding && d.misses >= m_poller.missLimit()) {
        d.responding = false;
        d.jog = Jog::Idle;
        d.motionPending = false;
        setPollInterval(m_userPollMs);
        Q_EMIT errorOccurred(tr("%1 stopped answering (%2 status polls unanswered)")
                                 .arg(driveName(d.axis))
                                 .arg(d.misses));
    }
}

void NanotecController::applyStatusWord(Drive& d, qint64 word)
{
    d.status = word;
    const DriveState s = decodeStatus(word);
    if (s.ready && d.motionPending) {
        d.motionPending = false;
        if (d.referencing) {
            d.referencing = false;
            AxisStatus& a = mutableStatus().axes[d.axis];
            a.referenced = !s.positionError;
            a.positionKnown = !s.positionError;
        }
    }
    if (s.positionError && !d.positionErrorReported) {
        d.positionErrorReported = true;
        Q_EMIT errorOccurred(tr("%1 reports a position error (encoder deviation above "
                                "max-encoder-deviation); reset it with reset-position-error")
                                 .arg(driveName(d.axis)));
    }
    if (!s.positionError)
        d.positionErrorReported = false;
}

void NanotecController::onUnsolicited(const Reply& reply)
{
    // 5.31: "j" + status word, sent by the drive itself at the end of a move.
    if (reply.kind != Reply::Kind::Echo || reply.key != "j" || !reply.value) {
        qCDebug(lcNanotec) << "unsolicited reply ignored:" << reply.raw;
        return;
    }
    for (Drive& d : m_drives) {
        if (d.address != reply.address)
            continue;
        noteAnswer(d, true);
        applyStatusWord(d, *reply.value);
        const Axis axis = d.axis;
        NanotecBus::Request r;
        r.address = d.address;
        r.body = "C";
        r.priority = NanotecBus::Priority::Poll;
        r.timeoutMs = pollTimeoutMs();
        r.poll = true;
        r.done = [this, axis](NanotecBus::Outcome o, const Reply& pos) {
            if (o == NanotecBus::Outcome::Ok && pos.value)
                m_drives[axis].position = *pos.value;
            updateStatus();
            publishStatus();
        };
        m_bus->submit(r);
        updateStatus();
        publishStatus();
        return;
    }
}

void NanotecController::updateStatus()
{
    MachineStatus& st = mutableStatus();
    st.drives.clear();
    bool busy = false, silent = false, responding = false;
    for (const Drive& d : m_drives) {
        AxisStatus& a = st.axes[d.axis];
        DriveStatus ds;
        ds.address = d.address;
        ds.axes = {d.axis};
        ds.responding = d.responding;
        ds.firmware = d.firmware;
        ds.detail = !d.responding ? tr("not answering")
                    : d.status    ? describeStatus(*d.status)
                                  : tr("no status yet");
        st.drives << ds;
        silent = silent || !d.responding;
        responding = responding || d.responding;
        const bool ready = d.status && decodeStatus(*d.status).ready;
        a.jogging = d.jog != Jog::Idle && !d.velocityMove;
        a.moving = !a.jogging && ((d.status && !ready) || d.jog != Jog::Idle || d.motionPending);
        busy = busy || a.moving || a.jogging;
        a.position = d.position;
        a.positionEstimated = false;
        if (d.inputs) {
            // 5.7: the external switch sits on input 6; a normally closed one reads low
            // when actuated. It is also the switch of the external reference run (6.6 p4).
            const bool high = *d.inputs & 0x20;
            a.limitSwitch = d.limitSwitchType == 0 ? !high : high;
            a.referenceSwitch = a.limitSwitch;
            st.raw.insert(QStringLiteral("inputs") + axisName(d.axis), *d.inputs);
        }
        if (d.status)
            st.raw.insert(QStringLiteral("status") + axisName(d.axis), *d.status);
        st.raw.insert(QStringLiteral("position") + axisName(d.axis), d.position);
    }
    const bool connected = linkState() == LinkState::Connected;
    st.busy = busy;
    st.driveOn = connected && responding;
    st.commFault = linkState() == LinkState::Lost || (connected && silent);
    st.panic = m_panic;
}

} // namespace stepdeck::nanotec
