// Status sweeps ('$', 'C' and now and then 'ZY' per drive), the auto status 'j' (5.31),
// silent drives and the normalised MachineStatus of a Nanotec bus.
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"

namespace stepdeck::nanotec {

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
        const QString deviation =
            ParameterSchema::displayLabel(findParam(QStringLiteral("max-encoder-deviation"))->spec);
        const QString how = options().actionNames.value(QStringLiteral("reset-position-error"));
        Q_EMIT errorOccurred(
            how.isEmpty()
                ? tr("%1 reports a position error (encoder deviation above %2); reset the "
                     "position error to go on")
                      .arg(driveName(d.axis), deviation)
                : tr("%1 reports a position error (encoder deviation above %2); reset it with %3")
                      .arg(driveName(d.axis), deviation, how));
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
        if (const QString run = m_closedLoop->runDetail(d.axis); !run.isEmpty() && d.responding)
            ds.detail = run + QStringLiteral("; ") + ds.detail; // mode 8/101 fit no status bits
        st.drives << ds;
        silent = silent || !d.responding;
        responding = responding || d.responding;
        const bool ready = d.status && decodeStatus(*d.status).ready;
        a.jogging = d.jog != Jog::Idle && !d.velocityMove;
        a.moving = !a.jogging && ((d.status && !ready) || d.jog != Jog::Idle || d.motionPending);
        a.motionUnknown = !d.responding; // a silent drive is never shown as idle
        busy = busy || a.moving || a.jogging || a.motionUnknown;
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
    if (connected && !busy && !jogActive())
        noteStandstillConfirmed(); // every drive answered and is ready
}

} // namespace stepdeck::nanotec
