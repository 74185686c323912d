#include "ElabController.h"
#include "ElabCtlParameters.h"
#include "ElabModel.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <QTimer>

namespace stepdeck::elab {

namespace {
// RS232-C: "Der Reset wird durch eine Logische 1 auf der RTS-Leitung ausgelöst. Diese muss
// mindestens für 100msec im High Zustand verharren ... Nachdem die Leitung auf Low gezogen
// wurde, sind weitere 100mSec zu warten." A margin on both.
constexpr int kResetPulseMs = 120;
constexpr int kResetSettleMs = 120;
constexpr int kTemperatureEveryNthPoll = 10;
constexpr int kStartButtonEveryNthPoll = 20;
} // namespace

ElabController::ElabController(Transport* transport, const ControllerOptions& options,
                               QObject* parent)
    : Controller(transport, options, parent), m_queue(transport, this),
      m_line(m_queue, mutableStatus(), hooks()),
      m_jog(m_line, ElabCtlJog::Hooks{[this] { haltJogImmediately(); },
                                      [this](const QString& why) { Q_EMIT jogRefused(why); },
                                      [this] { return linkState() == LinkState::Connected; }})
{
    MachineStatus& s = mutableStatus();
    for (Axis a : ElabCtlStatusMapper::axes())
        s.axes.insert(a, AxisStatus{});
    s.drives = {DriveStatus{0, ElabCtlStatusMapper::axes(), true, {}, {}}};

    m_queue.setTimeoutMs(options.commandTimeoutMs);
    m_poller.setInterval(options.pollIntervalMs);
    m_poller.setMissLimit(options.missedPollsForLinkLoss);
    connect(&m_poller, &StatusPoller::pollDue, this, &ElabController::startPoll);
    connect(&m_poller, &StatusPoller::rateChanged, this, &Controller::pollRateChanged);
    connect(&m_poller, &StatusPoller::linkLost, this, [this](int misses) {
        linkDown(tr("no reply to %1 status polls in a row").arg(misses), true);
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
                [this](const QString& reason) { linkDown(reason, false); });
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
        finishError(id, kind, message);
    };
    h.publish = [this] { publishStatus(); };
    h.statusRead = [this] { m_ops.onStatusRead(); };
    h.requireLink = [this](RequestId id) { return requireLink(id); };
    h.error = [this](const QString& message) { Q_EMIT errorOccurred(message); };
    return h;
}

bool ElabController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected)
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
        return tr("jog refused: setup incomplete (tmInvSetup): write start-speed, max-speed and "
                  "acceleration first");
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
    setLinkState(LinkState::Connecting);
    transport()->open(elab::lineSettings());
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
                m_written.clear(); // the board lost its setup (power cycle): nothing is known
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

void ElabController::linkDown(const QString& reason, bool closeTransport)
{
    // Reported once: a transport failure after the poller gave up (or the reverse) is the same
    // outage.
    if ((linkState() == LinkState::Disconnected || linkState() == LinkState::Lost) && m_openId == 0)
        return;
    m_poller.stop();
    const bool opening = m_openId != 0;
    cancelEverything(ErrorKind::LinkDown, tr("link lost: %1").arg(reason));
    if (closeTransport && transport())
        transport()->close();
    if (opening) {
        finishError(std::exchange(m_openId, 0), ErrorKind::LinkDown, reason);
        setLinkState(LinkState::Disconnected, reason);
        return;
    }
    setLinkState(LinkState::Lost, reason);
    Q_EMIT errorOccurred(tr("link lost: %1").arg(reason));
}

void ElabController::closeLink()
{
    m_poller.stop();
    Transport* t = transport();
    if (t && t->isOpen() && linkState() == LinkState::Connected &&
        (jogActive() || m_jog.inJogMode() || m_ops.openEnded())) {
        // Best effort: nothing may keep running unattended (jog, velocity or reference move,
        // stream).
        // "ForceStopMove stoppt sofort jegliche Bewegung mit Bremsrampen".
        const QByteArray stopByte = encode::stopMove();
        recordTraffic(TrafficRecord::Direction::Out, stopByte, false);
        t->write(stopByte);
    }
    cancelEverything(ErrorKind::Cancelled, tr("link closed"));
    if (m_openId != 0)
        finishError(std::exchange(m_openId, 0), ErrorKind::Cancelled, tr("link closed"));
    if (t)
        t->close();
    setLinkState(LinkState::Disconnected, tr("closed"));
}

void ElabController::startPoll()
{
    // The poll goes behind queued commands; it never has more than one cycle in flight.
    if (linkState() != LinkState::Connected || !m_poller.isDue())
        return;
    m_poller.pollStarted();
    ++m_pollCount;
    ElabCtlLine::StatusRead how;
    how.poll = true;
    how.temperature = m_pollCount % kTemperatureEveryNthPoll == 1;
    how.startButton = m_pollCount % kStartButtonEveryNthPoll == 0;
    m_line.readStatus(
        0, how, [this] { m_poller.pollFinished(true); },
        [this](ErrorKind kind, const QString&) {
            // Cancelled by panic/stop is not a missed reply; timeouts and garbage are.
            m_poller.pollFinished(kind != ErrorKind::Timeout && kind != ErrorKind::Protocol);
        });
}

void ElabController::setPollInterval(int ms)
{
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

// ------------------------------------------------------------------ stop, panic, reset

void ElabController::stop(RequestId id)
{
    if (!transport() || !transport()->isOpen() || linkState() != LinkState::Connected) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    const bool streaming = m_ops.streaming();
    m_line.newEpoch();
    // Work not yet written is dropped; polls stay (they are harmless and keep the status).
    m_queue.dropQueued(ErrorKind::Cancelled, tr("cancelled by stop"), false);
    m_ops.abortStream(ErrorKind::Cancelled, tr("feed stream stopped"));
    // "ForceStopMove stoppt sofort jegliche Bewegung mit Bremsrampen" -- jog included, so the
    // host ramp stops at once instead of fighting the board's brake ramp.
    haltJogImmediately();
    m_jog.reset();
    const ElabCtlLine::Op op = m_line.op(id);
    ElabExchange ex = ElabCtlLine::exchange(id, encode::stopMove(), Expect::AckNak);
    ex.onReply = [this, op, streaming](const Reply& r) {
        if (r.kind != Reply::Kind::Ack) {
            m_line.failWithNak(op, encode::stopMove());
            return;
        }
        m_ops.onStopAccepted(); // after the reply of what was in flight (FIFO)
        if (!streaming) {
            finishOk(op.id);
            return;
        }
        // A stop during <DC2>: the buffer still holds single steps; flush it and end the feed
        // ("Der Buffer kann jetzt mit folgendem Kommando geleert werden": <GS>; "Den Abschluss
        // ... muss immer ein EndOfFeed Kommando sein").
        m_line.sendCommand(op, encode::flushBuffer(), [this, op] {
            m_line.sendCommand(op, encode::endOfFeed(), [this, op] { finishOk(op.id); });
        });
    };
    ex.onError = [this, id](ErrorKind kind, const QString& why) { finishError(id, kind, why); };
    m_queue.overtake(std::move(ex), false);
    publishStatus();
}

void ElabController::panic(RequestId id)
{
    Transport* t = transport();
    if (!t || !t->isOpen()) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    const bool streaming = m_ops.streaming();
    const QString why = tr("cancelled by panic stop");
    m_line.newEpoch();
    m_ops.abortStream(ErrorKind::Cancelled, why);
    m_ops.clear();
    haltJogImmediately();
    m_jog.reset();
    m_queue.dropQueued(ErrorKind::Cancelled, why, true);
    m_queue.abandonInFlight(ErrorKind::Cancelled, why);
    // "Beim Wiederanlauf muss das System neu initialisiert werden, da ... Schritte verloren
    // gehen."
    markAllUnreferenced();
    m_line.setHostPanic(true);
    // Mid-stream the board may wait for the data byte of a <DC2> pair whose data byte was
    // discarded: a first <BEL> is then taken as the step byte 0x07 (no step bit set, harmless)
    // and the second one is the panic. Outside a stream the second <BEL> is a second panic.
    const QByteArray frame =
        streaming ? encode::panicStop() + encode::panicStop() : encode::panicStop();
    ElabExchange ex = ElabCtlLine::exchange(id, frame, Expect::Ack);
    ex.tolerateStray = true; // replies of abandoned exchanges may still come
    ex.onReply = [this, id](const Reply&) {
        finishOk(id);
        ElabCtlLine::StatusRead how;
        how.continuation = how.tolerant = true;
        m_line.readStatus(
            0, how, [] {}, [](ErrorKind, const QString&) {});
    };
    ex.onError = [this, id](ErrorKind kind, const QString& message) {
        finishError(id, kind, message);
    };
    m_queue.overtake(std::move(ex), true);
    publishStatus();
}

void ElabController::reset(RequestId id)
{
    Transport* t = transport();
    if (!t || !t->isOpen() || linkState() != LinkState::Connected) {
        finishError(id, ErrorKind::LinkDown, tr("not connected"));
        return;
    }
    cancelEverything(ErrorKind::Cancelled, tr("cancelled by reset"));
    markAllUnreferenced();
    publishStatus();
    QString error;
    if (!t->setResetLine(true, &error)) {
        finishError(id, ErrorKind::Unsupported, tr("reset not possible: %1").arg(error));
        return;
    }
    m_poller.stop();
    m_queue.setHeld(true);
    const quint64 epoch = m_line.epoch();
    QTimer::singleShot(kResetPulseMs, this, [this, id, epoch] {
        if (epoch != m_line.epoch() || !transport())
            return; // link lost meanwhile: the request was already finished
        QString ignored;
        transport()->setResetLine(false, &ignored);
        QTimer::singleShot(kResetSettleMs, this, [this, id, epoch] { finishReset(id, epoch); });
    });
}

void ElabController::finishReset(RequestId id, quint64 epoch)
{
    if (epoch != m_line.epoch())
        return;
    m_queue.setHeld(false);
    m_line.setHostPanic(false);
    m_written.clear(); // a reset board has lost its setup
    ElabCtlLine::StatusRead how;
    how.temperature = how.tolerant = true;
    m_line.readStatus(
        id, how,
        [this, id] {
            m_poller.start();
            finishOk(id);
        },
        [this, id](ErrorKind kind, const QString& why) {
            m_poller.start();
            finishError(id, kind, tr("no status after reset: %1").arg(why));
        });
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
    const QString note =
        verify ? tr("written; the E-LAB board cannot read parameters back, nothing verified")
               : QString();
    writeStep(m_line.op(id), plan, 0, note);
}

void ElabController::writeStep(const ElabCtlLine::Op& op, const QList<ElabParameterWrite>& plan,
                               int index, const QString& note)
{
    // One setup command after the other; a NAK stops the sequence (the rest is not sent).
    if (index == plan.size()) {
        finish(CommandResult{op.id, ErrorKind::None, note, {}});
        return;
    }
    m_line.sendCommand(
        op, plan.at(index).frame,
        [this, op, plan, index, note] {
            m_written.insert(plan.at(index).name, plan.at(index).value);
            writeStep(op, plan, index + 1, note);
        },
        index > 0);
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
    m_line.sendCommand(
        m_line.op(id), frame,
        [this, id, name, value] {
            m_written.insert(name, ParameterValue{value, {}});
            finishOk(id);
        },
        false);
}

void ElabController::setSpindle(RequestId id, int rpm)
{
    // SetSpindleRPM: "einen Wert zwischen 0 und 1000 in einem long Hex-Word".
    if (rpm < 0 || rpm > 1000) {
        finishError(id, ErrorKind::InvalidValue,
                    tr("spindle-rpm: value '%1' is out of range (allowed: 0..1000 rpm)").arg(rpm));
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
        finishError(id, ErrorKind::InvalidValue,
                    tr("drive-power: value '%1' is out of range (allowed: 0..100 %)").arg(percent));
        return;
    }
    writeAuxiliary(id, QStringLiteral("drive-power"), qint64(percent),
                   encode::drivePower(quint8(percent)));
}

} // namespace stepdeck::elab
