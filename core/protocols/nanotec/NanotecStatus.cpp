// Initialisation, status sweeps and the normalised status of a Nanotec bus (NanotecStatus.h).
#include "NanotecStatus.h"
#include "Logging.h"
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "NanotecLogging.h"
#include "NanotecModel.h"
#include "transport/Transport.h"
#include <QtMath>

namespace stepdeck::nanotec {

namespace {
// Status reads are idempotent: one garbled or lost reply (line noise) is asked again before
// the request fails (issue 12: occasional noise is survived, persistent garbage fails).
constexpr NanotecBus::Priority kStatusPriority = NanotecBus::Priority::Command;
constexpr int kStatusRetries = 1;
// 5.7: the external (limit/reference) switch sits on input 6.
constexpr qint64 kSwitchInput = 0x20;
} // namespace

NanotecStatus::NanotecStatus(NanotecController& controller)
    : m_plan(lineSettings().characterTimeUs()), m_ctl(controller), m_link(controller.m_exchange)
{}

int NanotecStatus::sweepBudgetMs() const
{
    // Per drive and sweep: "#1$\r" + "001$17\r" + "#1C\r" + "001C-1234567\r" = 27 characters,
    // plus a quarter of "#1ZY\r" + "001ZY196671\r" for the inputs: about 31 characters.
    int drives = 0;
    for (const HostDrive& d : m_ctl.m_drives)
        drives += d.responding ? 1 : 0;
    const double us = qMax(1, drives) * 31 * lineSettings().characterTimeUs();
    return int(qCeil(us / 1000.0));
}

int NanotecStatus::pollTimeoutMs() const
{
    // A status reply is under 15 characters (8 ms at 19200 baud): a short timeout keeps a
    // silent drive from stalling the sweep of the others.
    return qMin(m_ctl.options().commandTimeoutMs, 150);
}

void NanotecStatus::initialiseDrives()
{
    m_ctl.m_initialising = true;
    QList<Step> perDrive;
    for (Axis axis : m_ctl.m_drives.keys())
        perDrive << initialiseDrive(axis);
    runSteps(perDrive, [this](const Failure&) { finishInitialising(); });
}

Step NanotecStatus::initialiseDrive(Axis axis)
{
    // Firmware first (5.22): a drive that does not answer it is flagged and skipped; the
    // rest only fills caches, so a drive that answers but refuses one of them stays.
    Step identify = m_link.exchange(
        axis, "v",
        [this, axis](const Reply& r) {
            m_ctl.m_drives[axis].firmware = r.firmware.text;
            return Failure{};
        },
        NanotecBus::Priority::Command, 1);
    QList<Step> rest{
        // Auto status off (5.31): on a polled half-duplex bus a 'j' the drive sends by
        // itself collides with the poll of another drive.
        tolerant(m_link.exchange(axis, "J0")),
        tolerant(m_link.exchange(axis, "Ze", sink([this, axis](qint64 v) {
                                     m_ctl.m_drives[axis].limitSwitchType = v;
                                 }))),
        tolerant(m_link.exchange(
            axis, "Zu", sink([this, axis](qint64 v) { m_ctl.m_drives[axis].minFrequency = v; }))),
        tolerant(m_link.exchange(
            axis, "Zo", sink([this, axis](qint64 v) { m_ctl.m_drives[axis].maxFrequency = v; }))),
        tolerant(m_link.exchange(axis, "Zb",
                                 sink([this, axis](qint64 v) { m_ctl.m_drives[axis].ramp = v; }))),
        tolerant(m_link.exchange(
            axis, "$", sink([this, axis](qint64 v) { applyStatusWord(m_ctl.m_drives[axis], v); }))),
        tolerant(m_link.exchange(
            axis, "C", sink([this, axis](qint64 v) { m_ctl.m_drives[axis].position = v; }))),
    };
    return [this, axis, identify, rest](const Done& done) {
        identify([this, axis, rest, done](const Failure& f) {
            HostDrive& d = m_ctl.m_drives[axis];
            d.responding = f.kind != ErrorKind::Timeout && f.kind != ErrorKind::Cancelled;
            d.misses = d.responding ? 0 : m_ctl.m_poller.missLimit();
            if (!f.ok())
                qCWarning(lcNanotec) << "initialising" << m_ctl.driveName(axis) << ":" << f.message;
            if (!d.responding)
                return done({});
            runSteps(rest, [done](const Failure&) { done({}); });
        });
    };
}

void NanotecStatus::finishInitialising()
{
    m_ctl.m_initialising = false;
    QStringList silent;
    for (const HostDrive& d : m_ctl.m_drives) {
        if (!d.responding)
            silent << QString::number(d.address);
    }
    const RequestId id = m_ctl.m_pendingOpen;
    m_ctl.m_pendingOpen = 0;
    if (silent.size() == m_ctl.m_drives.size()) {
        const QString why = tr("no drive answered at address %1 (19200 baud 8N1)")
                                .arg(silent.join(QStringLiteral(", ")));
        if (m_ctl.transport())
            m_ctl.transport()->close();
        m_ctl.setLinkState(LinkState::Disconnected, why);
        m_ctl.finishError(id, ErrorKind::Timeout, why);
        return;
    }
    m_ctl.setLinkState(LinkState::Connected);
    m_ctl.setPollInterval(m_ctl.m_userPollMs);
    m_ctl.m_poller.start();
    updateStatus();
    m_ctl.publishStatus();
    if (!silent.isEmpty())
        Q_EMIT m_ctl.errorOccurred(tr("no answer from drive %1; the other drives work")
                                       .arg(silent.join(QStringLiteral(", "))));
    m_ctl.finishOk(id);
}

void NanotecStatus::refreshStatus(RequestId id)
{
    if (m_ctl.linkState() != LinkState::Connected)
        return m_ctl.finishError(id, ErrorKind::LinkDown, tr("not connected"));
    QList<Step> steps;
    auto answered = std::make_shared<int>(0);
    for (Axis axis : m_ctl.m_drives.keys()) {
        auto ok = std::make_shared<bool>(false);
        steps << tolerant([this, axis, ok, answered](const Done& done) {
            runSteps(
                {m_link.exchange(axis, "$", sink([this, axis, ok, answered](qint64 v) {
                                     applyStatusWord(m_ctl.m_drives[axis], v);
                                     *ok = true;
                                     ++*answered;
                                 }),
                                 kStatusPriority, kStatusRetries),
                 m_link.exchange(
                     axis, "C", sink([this, axis](qint64 v) { m_ctl.m_drives[axis].position = v; }),
                     kStatusPriority, kStatusRetries),
                 m_link.exchange(axis, "ZY",
                                 sink([this, axis](qint64 v) { m_ctl.m_drives[axis].inputs = v; }),
                                 kStatusPriority, kStatusRetries)},
                [this, axis, ok, done](const Failure& f) {
                    if (!*ok && f.kind == ErrorKind::Timeout)
                        noteAnswer(m_ctl.m_drives[axis], false);
                    done(f);
                });
        });
    }
    runSteps(steps, [this, id, answered](const Failure& f) {
        updateStatus();
        m_ctl.publishStatus();
        if (!f.ok())
            return m_ctl.finishWith(id, f);
        if (*answered == 0)
            return m_ctl.finishError(id, ErrorKind::Timeout,
                                     tr("no drive answered the status request"));
        m_ctl.finishOk(id, QVariant::fromValue(m_ctl.status()));
    });
}

void NanotecStatus::onPollDue()
{
    if (m_ctl.linkState() != LinkState::Connected || m_ctl.m_initialising ||
        m_ctl.m_poller.isPollInFlight())
        return;
    if (m_ctl.m_bus->hasQueued(NanotecBus::Priority::Urgent) ||
        m_ctl.m_bus->hasQueued(NanotecBus::Priority::Command))
        return; // commands first; the poller reminds us after an interval
    // Issue 32: the plan bounds the sweep (NanotecPollPlan.h): moving drives every sweep, the
    // idle ones in turn. While a positioning run is pending the running drives' positions are
    // read every other sweep (issue 30: the next chord waits for the sweep that sees the last
    // one arrive).
    bool anyRuns = false; // never an empty sweep: that would count as a miss
    QList<NanotecPollPlan::Drive> drives;
    for (const HostDrive& d : std::as_const(m_ctl.m_drives)) {
        anyRuns = anyRuns || (d.motionPending && d.responding);
        // A jogging drive is active too: its soft limits are judged on its position.
        const bool active = d.motionPending || d.jog != JogPhase::Idle || d.velocityMove;
        drives << NanotecPollPlan::Drive{d.axis, active, d.responding};
    }
    const QList<NanotecPollPlan::Read> sweep =
        m_plan.next(drives, anyRuns && m_ctl.m_poller.isExpedited());
    m_ctl.m_poller.pollStarted();
    pollDrive(sweep, std::make_shared<bool>(false));
}

void NanotecStatus::pollDrive(QList<NanotecPollPlan::Read> remaining,
                              std::shared_ptr<bool> answered)
{
    if (remaining.isEmpty()) {
        paceForMotion(); // before pollFinished(), which schedules the next sweep
        m_ctl.m_poller.pollFinished(*answered);
        updateStatus();
        m_ctl.publishStatus();
        return;
    }
    const NanotecPollPlan::Read read = remaining.takeFirst();
    const Axis axis = read.axis;
    const PollRequest request = [this, axis](const QByteArray& body, NanotecBus::Handler done) {
        NanotecBus::Request r;
        r.address = m_ctl.m_drives[axis].address;
        r.body = body;
        r.priority = NanotecBus::Priority::Poll;
        r.timeoutMs = pollTimeoutMs();
        r.poll = true;
        r.done = std::move(done);
        m_ctl.m_bus->submit(r);
    };
    auto next = [this, remaining, answered] { pollDrive(remaining, answered); };
    using O = NanotecBus::Outcome;
    request("$", [=](O o, const Reply& r) {
        if (o == O::Cancelled)
            return m_ctl.m_poller.pollFinished(true); // stop/panic/disconnect took the bus
        HostDrive& d = m_ctl.m_drives[axis];
        noteAnswer(d, o != O::Timeout);
        if (o != O::Ok || !r.value)
            return next();
        *answered = true;
        const bool wasPending = d.motionPending;
        const bool changed = d.status != r.value;
        applyStatusWord(d, *r.value);
        // 'C' of a running drive as the plan says; of a drive at rest on its turn, and
        // always when its status changed or its run just ended (the arrival's position).
        const bool position =
            d.motionPending ? read.positionWhileRunning : read.position || changed || wasPending;
        if (!position)
            return read.inputs ? readInputs(axis, request, next) : next();
        request("C", [=](O o2, const Reply& r2) {
            if (o2 == O::Cancelled)
                return m_ctl.m_poller.pollFinished(true);
            if (o2 == O::Ok && r2.value)
                m_ctl.m_drives[axis].position = *r2.value;
            if (wasPending && !m_ctl.m_drives[axis].motionPending)
                publishIfArrived();
            if (!read.inputs)
                return next();
            readInputs(axis, request, next);
        });
    });
}

void NanotecStatus::publishIfArrived()
{
    // Issue 30: the last drive of a run just read at rest, its position with it: the next
    // chord waits for this status, not for the rest of the sweep (idle drives, inputs).
    for (const HostDrive& d : std::as_const(m_ctl.m_drives)) {
        if (d.motionPending && d.responding)
            return;
    }
    updateStatus();
    m_ctl.publishStatus();
}

void NanotecStatus::readInputs(Axis axis, const PollRequest& request,
                               const std::function<void()>& next)
{
    using O = NanotecBus::Outcome;
    request("ZY", [=](O o, const Reply& r) {
        if (o == O::Cancelled)
            return m_ctl.m_poller.pollFinished(true);
        if (o != O::Ok || !r.value)
            return next();
        const std::optional<qint64> held = m_ctl.m_drives[axis].inputs;
        if (!held || ((*held ^ *r.value) & kSwitchInput) == 0) {
            m_ctl.m_drives[axis].inputs = *r.value;
            return next();
        }
        // The switch input changed. A digit of line noise inside the value changes it just
        // as well and the protocol has no checksum: a second read must agree before a limit
        // switch is reported (or cleared). Otherwise the last value stays until the next
        // sweep with the inputs.
        const qint64 first = *r.value;
        request("ZY", [=](O o2, const Reply& r2) {
            if (o2 == O::Cancelled)
                return m_ctl.m_poller.pollFinished(true);
            if (o2 == O::Ok && r2.value && ((*r2.value ^ first) & kSwitchInput) == 0)
                m_ctl.m_drives[axis].inputs = *r2.value;
            next();
        });
    });
}

void NanotecStatus::paceForMotion()
{
    // A program's next block waits for the sweep that finds its drives ready; at the user's
    // interval that is up to an interval plus a sweep (50 + 11 ms at 19200 baud) after the
    // arrival, at the expedited pace at most about two sweeps.
    bool pending = false;
    for (const HostDrive& d : std::as_const(m_ctl.m_drives))
        pending = pending || (d.motionPending && d.responding);
    m_ctl.m_poller.setExpedited(pending);
}

void NanotecStatus::noteAnswer(HostDrive& d, bool answered)
{
    if (answered) {
        d.misses = 0;
        if (!d.responding) {
            d.responding = true;
            qCInfo(lcNanotec) << m_ctl.driveName(d.axis) << "answers again";
            m_ctl.setPollInterval(m_ctl.m_userPollMs);
            // Safety contract: a drive that fell silent may have been switched off and on
            // (it then counts from 0, 5.17) or moved by hand; after a reconnect positions are
            // unknown until referenced.
            AxisStatus& a = m_ctl.mutableStatus().axes[d.axis];
            if (a.positionKnown || a.referenced) {
                a.referenced = a.positionKnown = false;
                Q_EMIT m_ctl.errorOccurred(
                    tr("%1 answers again after a silence: it may have been switched off and on; "
                       "its position is unknown, reference axis %2")
                        .arg(m_ctl.driveName(d.axis), m_ctl.nameOf(d.axis)));
            }
        }
        return;
    }
    ++d.misses;
    if (d.responding && d.misses >= m_ctl.m_poller.missLimit()) {
        d.responding = false;
        d.jog = JogPhase::Idle;
        d.motionPending = false;
        m_ctl.setPollInterval(m_ctl.m_userPollMs);
        Q_EMIT m_ctl.errorOccurred(tr("%1 stopped answering (%2 status polls unanswered)")
                                       .arg(m_ctl.driveName(d.axis))
                                       .arg(d.misses));
    }
}

void NanotecStatus::applyStatusWord(HostDrive& d, qint64 word)
{
    d.status = word;
    const DriveState s = decodeStatus(word);
    if (s.ready && d.motionPending) {
        d.motionPending = false;
        if (d.referencing) {
            d.referencing = false;
            AxisStatus& a = m_ctl.mutableStatus().axes[d.axis];
            a.referenced = !s.positionError;
            a.positionKnown = !s.positionError;
        }
    }
    if (s.positionError && !d.positionErrorReported) {
        d.positionErrorReported = true;
        const QString deviation =
            ParameterSchema::displayLabel(findParam(QStringLiteral("max-encoder-deviation"))->spec);
        const QString how =
            m_ctl.options().actionNames.value(QStringLiteral("reset-position-error"));
        Q_EMIT m_ctl.errorOccurred(
            how.isEmpty()
                ? tr("%1 reports a position error (encoder deviation above %2); reset the "
                     "position error to go on")
                      .arg(m_ctl.driveName(d.axis), deviation)
                : tr("%1 reports a position error (encoder deviation above %2); reset it with %3")
                      .arg(m_ctl.driveName(d.axis), deviation, how));
    }
    if (!s.positionError)
        d.positionErrorReported = false;
}

void NanotecStatus::onUnsolicited(const Reply& reply)
{
    // 5.31: "j" + status word, sent by the drive itself at the end of a move.
    if (reply.kind != Reply::Kind::Echo || reply.key != "j" || !reply.value) {
        qCDebug(lcNanotec) << "unsolicited reply ignored:" << reply.raw;
        return;
    }
    for (HostDrive& d : m_ctl.m_drives) {
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
                m_ctl.m_drives[axis].position = *pos.value;
            updateStatus();
            m_ctl.publishStatus();
        };
        m_ctl.m_bus->submit(r);
        updateStatus();
        m_ctl.publishStatus();
        return;
    }
}

void NanotecStatus::updateStatus()
{
    MachineStatus& st = m_ctl.mutableStatus();
    st.drives.clear();
    bool busy = false, silent = false, responding = false;
    for (const HostDrive& d : m_ctl.m_drives) {
        AxisStatus& a = st.axes[d.axis];
        DriveStatus ds;
        ds.address = d.address;
        ds.axes = {d.axis};
        ds.responding = d.responding;
        ds.firmware = d.firmware;
        ds.detail = !d.responding ? tr("not answering")
                    : d.status    ? describeStatus(*d.status)
                                  : tr("no status yet");
        if (const QString run = m_ctl.m_closedLoop->runDetail(d.axis);
            !run.isEmpty() && d.responding)
            ds.detail = run + QStringLiteral("; ") + ds.detail; // mode 8/101 fit no status bits
        st.drives << ds;
        silent = silent || !d.responding;
        responding = responding || d.responding;
        const bool ready = d.status && decodeStatus(*d.status).ready;
        a.jogging = d.jog != JogPhase::Idle && !d.velocityMove;
        a.moving =
            !a.jogging && ((d.status && !ready) || d.jog != JogPhase::Idle || d.motionPending);
        a.motionUnknown = !d.responding; // a silent drive is never shown as idle
        busy = busy || a.moving || a.jogging || a.motionUnknown;
        a.position = d.position;
        a.positionEstimated = false;
        if (d.inputs) {
            // 5.7: the external switch sits on input 6; a normally closed one reads low
            // when actuated. It is also the switch of the external reference run (6.6 p4).
            const bool high = *d.inputs & kSwitchInput;
            a.limitSwitch = d.limitSwitchType == 0 ? !high : high;
            a.referenceSwitch = a.limitSwitch;
            st.raw.insert(QStringLiteral("inputs") + axisName(d.axis), *d.inputs);
        }
        if (d.status)
            st.raw.insert(QStringLiteral("status") + axisName(d.axis), *d.status);
        st.raw.insert(QStringLiteral("position") + axisName(d.axis), d.position);
    }
    const bool connected = m_ctl.linkState() == LinkState::Connected;
    st.busy = busy;
    st.driveOn = connected && responding;
    st.commFault = m_ctl.linkState() == LinkState::Lost || (connected && silent);
    st.panic = m_ctl.m_panic;
    if (connected && !busy && !m_ctl.jogActive())
        m_ctl.noteStandstillConfirmed(); // every drive answered and is ready
}

} // namespace stepdeck::nanotec
