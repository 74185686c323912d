// The laser side of the bridge: the laser port, its frames, the answers and the log.
#include "LaserBridge.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QtMath>

namespace stepdeck::bridge {

using namespace stepdeck::laser;

namespace {
constexpr int kShutdownStopMs = 3000; // the controller's stop gets this long at shutdown
}

LaserBridge::LaserBridge(ControllerSession* session, Transport* laserPort,
                         const LaserBridgeConfig& config, QObject* parent)
    : QObject(parent), m_session(session), m_laser(laserPort), m_config(config),
      m_answers(config.scale),
      m_motion(session, m_config, m_caps, m_answers, m_slots, motionHooks())
{
    qRegisterMetaType<stepdeck::bridge::LaserBridge::LogEntry>();
    qRegisterMetaType<stepdeck::bridge::LaserBridge::AxisView>();
    for (auto it = config.axisMap.cbegin(); it != config.axisMap.cend(); ++it) {
        Slot slot;
        slot.laserAxis = it.key();
        slot.axis = it.value();
        m_slots.insert(it.key(), slot);
    }
    m_shutdownTimeout.setSingleShot(true);
    m_shutdownTimeout.setInterval(kShutdownStopMs);
    connect(&m_shutdownTimeout, &QTimer::timeout, this, [this] {
        log(LogEntry::Kind::Error, tr("the controller did not confirm the stop in time"));
        finishShutdown();
    });
    if (m_laser) {
        connect(m_laser, &Transport::opened, this, &LaserBridge::onLaserOpened);
        connect(m_laser, &Transport::failed, this, &LaserBridge::onLaserFailed);
        connect(m_laser, &Transport::dataReceived, this, &LaserBridge::onLaserData);
    }
    if (m_session) {
        connect(m_session, &ControllerSession::requestFinished, this,
                [this](const CommandResult& result) { m_motion.onResult(result); });
        connect(m_session, &ControllerSession::statusChanged, this, &LaserBridge::onStatus);
        connect(m_session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
            m_motion.onLinkState(state, m_running && !m_shuttingDown);
        });
    }
}

LaserBridge::~LaserBridge()
{
    if (m_laser && m_laser->isOpen()) {
        QSignalBlocker block(m_laser);
        m_laser->close();
    }
}

void LaserBridge::start()
{
    if (!m_session || !m_laser) {
        Q_EMIT failed(tr("no controller session or laser port"));
        return;
    }
    m_caps = m_session->capabilities();
    if (const QString bad = m_config.validate(m_caps); !bad.isEmpty()) {
        Q_EMIT failed(bad);
        return;
    }
    m_shuttingDown = false;
    m_laser->open(laser::lineSettings());
}

void LaserBridge::onLaserOpened()
{
    if (m_running)
        return;
    m_running = true;
    m_decoder.reset();
    log(LogEntry::Kind::Note,
        tr("serving the laser on %1 (9600 8N1): laser axes %2, %3 steps per laser unit")
            .arg(m_laser->description(), m_config.mapText())
            .arg(m_config.scale));
    for (const Slot& slot : std::as_const(m_slots))
        publish(slot);
    Q_EMIT started();
}

void LaserBridge::onLaserFailed(const QString& reason)
{
    const bool wasRunning = m_running;
    log(LogEntry::Kind::Error, tr("laser port: %1").arg(reason));
    if (wasRunning && !m_shuttingDown)
        shutdown(); // nobody to answer to: end what the bridge started
    Q_EMIT failed(reason);
}

void LaserBridge::onLaserData(const QByteArray& bytes)
{
    for (const DecodedCommand& d : m_decoder.feed(bytes)) {
        if (!d.ok()) {
            log(LogEntry::Kind::Ignored,
                tr("ignored malformed frame: %1").arg(describeError(d.error)), d.raw);
            continue;
        }
        log(LogEntry::Kind::FromLaser, commandText(*d.frame), d.raw);
        onCommand(*d.frame);
    }
}

void LaserBridge::onCommand(const CommandFrame& frame)
{
    if (!m_slots.contains(frame.axis)) {
        log(LogEntry::Kind::Ignored,
            tr("laser axis %1 is not mapped to a controller axis").arg(axisNumber(frame.axis)));
        return;
    }
    if (m_shuttingDown) {
        log(LogEntry::Kind::Ignored, tr("the bridge is stopping"));
        return;
    }
    Slot& slot = m_slots[frame.axis];
    slot.wanted = frame;
    slot.waitingForIdle = false;
    slot.failure.clear();
    if (m_doorOpen) {
        log(LogEntry::Kind::Note,
            tr("door open: %1 waits until the door closes").arg(commandText(frame)));
    } else if (m_motion.stopping()) {
        // The stop under way ends in redispatchAll(), which takes the newest target.
    } else if (slot.job.kind != Job::Kind::None) {
        m_motion.retarget(slot);
    } else {
        m_motion.dispatch(slot);
    }
    publish(slot);
}

LaserBridgeMotion::Hooks LaserBridge::motionHooks()
{
    LaserBridgeMotion::Hooks hooks;
    hooks.reply = [this](Slot& slot, const LaserAnswer& answer) { reply(slot, answer); };
    hooks.drop = [this](Slot& slot, const QString& why) { drop(slot, why); };
    hooks.publish = [this](const Slot& slot) { publish(slot); };
    hooks.log = [this](LogEntry::Kind kind, const QString& text) { log(kind, text); };
    hooks.stopEnded = [this] {
        if (std::exchange(m_doorReportPending, false))
            reportDoor(true); // the '3' waited for the stop to settle
    };
    hooks.finishShutdown = [this] { finishShutdown(); };
    hooks.doorOpen = [this] { return m_doorOpen; };
    hooks.shuttingDown = [this] { return m_shuttingDown; };
    return hooks;
}

void LaserBridge::onStatus(const MachineStatus& status)
{
    if (!m_running || m_shuttingDown)
        return;
    if (m_config.doorInput) {
        if (const std::optional<bool> open = doorInputState(status, *m_config.doorInput))
            setDoorOpen(*open);
    }
    m_motion.onStatus();
}

void LaserBridge::drop(Slot& slot, const QString& why)
{
    slot.failure =
        tr("%1: %2; no answer to the laser (it raises its timeout alarm)")
            .arg(slot.wanted ? commandText(*slot.wanted) : axisName(slot.laserAxis), why);
    log(LogEntry::Kind::Error, slot.failure);
    slot.wanted.reset();
    slot.waitingForIdle = false;
    publish(slot);
}

void LaserBridge::reply(Slot& slot, const LaserAnswer& answer)
{
    if (!answer.sent())
        return drop(slot, answer.withheld);
    send(slot, *answer.frame);
}

void LaserBridge::send(Slot& slot, const StatusFrame& frame)
{
    const QByteArray bytes = encodeStatus(frame);
    slot.lastAnswer = frame;
    if (frame.status != Status::DoorOpened && frame.status != Status::DoorClosed)
        slot.wanted.reset();
    if (m_laser && m_laser->isOpen())
        m_laser->write(bytes);
    log(LogEntry::Kind::ToLaser, statusText(frame), bytes.left(kBodySize));
    publish(slot);
}

void LaserBridge::setDoorOpen(bool open)
{
    if (open == m_doorOpen || !m_running || m_shuttingDown)
        return;
    m_doorOpen = open;
    log(LogEntry::Kind::Note, open ? tr("door opened") : tr("door closed"));
    if (open) {
        for (Slot& slot : m_slots)
            slot.waitingForIdle = false;
        // "after it has stopped due to any error (when detecting the ... doorswitch ...)":
        // the '3' goes out once the axes stand, with the positions they stopped at.
        m_motion.requestStop();
        if (!m_motion.stopping())
            reportDoor(true);
        else
            m_doorReportPending = true;
        return;
    }
    if (std::exchange(m_doorReportPending, false))
        reportDoor(true);
    reportDoor(false);
    if (!m_motion.stopping())
        m_motion
            .redispatchAll(); // "it should not prevent the motor from trying to reach its target"
}

void LaserBridge::reportDoor(bool open)
{
    // Reading of the manual: each axis that stopped for the door reports it; with none on its
    // way to a target the first mapped axis that can reports it for the machine. An axis whose
    // position is unknown cannot (every frame carries the position): that is an error.
    QList<Axis> reporting;
    for (const Slot& slot : std::as_const(m_slots)) {
        if (slot.wanted)
            reporting << slot.laserAxis;
    }
    const bool forMachine = reporting.isEmpty();
    if (forMachine)
        reporting = m_slots.keys();
    QStringList untold;
    for (Axis a : std::as_const(reporting)) {
        Slot& slot = m_slots[a];
        const AxisStatus axis =
            m_session ? m_session->status().axes.value(slot.axis) : AxisStatus{};
        const LaserAnswer answer = m_answers.door(a, slot.axis, axis, open);
        if (!answer.sent()) {
            untold << answer.withheld;
            continue;
        }
        send(slot, *answer.frame);
        if (forMachine)
            return;
    }
    if (!untold.isEmpty()) {
        log(LogEntry::Kind::Error,
            tr("not reported to the laser: %1").arg(untold.join(QStringLiteral("; "))));
    }
}

void LaserBridge::shutdown()
{
    if (m_shuttingDown)
        return;
    m_shuttingDown = true;
    if (m_session && m_session->linkState() != LinkState::Connected)
        m_motion.dropTargetsOfLostLink(); // they cannot be reached: say so before letting go
    bool busy = m_motion.stopping();
    for (Slot& slot : m_slots) {
        busy = busy || slot.job.kind != Job::Kind::None;
        slot.wanted.reset();
        slot.waitingForIdle = false;
    }
    if (busy && m_session && m_caps.stopCommand && m_session->linkState() == LinkState::Connected) {
        log(LogEntry::Kind::Note, tr("stopping the motion the bridge started"));
        m_motion.stopForShutdown();
        m_shutdownTimeout.start();
        return;
    }
    if (busy && !m_caps.stopCommand) {
        log(LogEntry::Kind::Error,
            tr("the controller has no stop command: the axes go on to their targets; use the "
               "machine's emergency stop to stop them"));
    }
    finishShutdown();
}

void LaserBridge::finishShutdown()
{
    m_shutdownTimeout.stop();
    m_motion.clearStop();
    for (Slot& slot : m_slots) {
        slot.job = Job{};
        publish(slot);
    }
    const bool wasRunning = m_running;
    m_running = false;
    if (m_laser && m_laser->isOpen())
        m_laser->close();
    if (wasRunning)
        log(LogEntry::Kind::Note, tr("laser bridge stopped"));
    Q_EMIT finished();
}

void LaserBridge::log(LogEntry::Kind kind, const QString& text, const QByteArray& frame)
{
    LogEntry entry{QDateTime::currentDateTime(), kind, frame, text};
    qCInfo(lcBridge).noquote() << formatLogEntry(entry);
    Q_EMIT logged(entry);
}

std::optional<bool> LaserBridge::doorInputState(const MachineStatus& status, int input)
{
    const QVariant inputs = status.raw.value(QStringLiteral("inputs"));
    if (!inputs.isValid() || input < 1 || input > 64)
        return std::nullopt;
    return (inputs.toULongLong() >> (input - 1)) & 1u;
}

QString LaserBridge::phaseName(Phase phase)
{
    switch (phase) {
    case Phase::Idle:
        return tr("idle");
    case Phase::Referencing:
        return tr("referencing");
    case Phase::Moving:
        return tr("moving");
    case Phase::Waiting:
        return tr("waiting for the controller");
    case Phase::Stopping:
        return tr("stopping to retarget");
    case Phase::Failed:
        return tr("target not reached");
    }
    return {};
}

QList<LaserBridge::AxisView> LaserBridge::axes() const
{
    QList<AxisView> out;
    for (const Slot& slot : m_slots) {
        AxisView view;
        view.laserAxis = slot.laserAxis;
        view.controllerAxis = slot.axis;
        view.target = slot.wanted;
        view.referenced = slot.referenced;
        view.lastAnswer = slot.lastAnswer;
        view.failure = slot.failure;
        if (m_motion.stopping() && slot.job.kind != Job::Kind::None)
            view.phase = Phase::Stopping;
        else if (slot.job.kind == Job::Kind::Reference)
            view.phase = Phase::Referencing;
        else if (slot.job.kind == Job::Kind::Move)
            view.phase = Phase::Moving;
        else if (slot.waitingForIdle || (slot.wanted && m_doorOpen))
            view.phase = Phase::Waiting;
        else if (!slot.failure.isEmpty())
            view.phase = Phase::Failed;
        out << view;
    }
    return out;
}

void LaserBridge::publish(const Slot& slot)
{
    for (const AxisView& view : axes()) {
        if (view.laserAxis == slot.laserAxis)
            Q_EMIT axisChanged(view);
    }
}

} // namespace stepdeck::bridge
