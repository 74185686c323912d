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
    : Controller(transport, options, parent), m_queue(transport, this)
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
        if (!ok)
            return;
        m_machineWord = word;
        ElabCtlStatusMapper::applyMachineState(mutableStatus(), word, m_hostPanic);
        publishStatus();
    });
    connect(&m_queue, &ElabExchangeQueue::flowControl, this, [this](bool resume) {
        if (!m_stream.isActive())
            return; // XON/XOFF outside a stream: nothing to pause
        m_stream.pausedByDevice = !resume;
        pumpStream();
    });
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

// ------------------------------------------------------------------ sequences

ElabExchange ElabController::exchange(RequestId owner, const QByteArray& frame, Expect expect) const
{
    ElabExchange ex;
    ex.owner = owner;
    ex.frame = frame;
    ex.expect = expect;
    return ex;
}

void ElabController::chain(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
                           ErrorFn failed)
{
    if (steps.isEmpty()) {
        done();
        return;
    }
    ElabExchange ex = steps.takeFirst();
    auto handler = ex.onReply;
    ex.onReply = [this, handler, steps, done, failed](const Reply& r) {
        if (handler)
            handler(r);
        chain(steps, true, done, failed);
    };
    ex.onError = failed;
    if (continuation)
        m_queue.enqueueNext(std::move(ex));
    else
        m_queue.enqueue(std::move(ex));
}

void ElabController::readStatus(RequestId owner, StatusRead how, std::function<void()> done,
                                ErrorFn failed)
{
    QList<ElabExchange> steps;
    ElabExchange ht = exchange(owner, encode::requestAxeState(), Expect::AxeState);
    ht.onReply = [this](const Reply& r) {
        m_axeWord = r.axeState;
        ElabCtlStatusMapper::applyAxeState(mutableStatus(), r.axeState);
    };
    ElabExchange enq = exchange(owner, encode::requestMachineState(), Expect::MachineState);
    enq.onReply = [this](const Reply& r) {
        m_machineWord = r.machineState;
        ElabCtlStatusMapper::applyMachineState(mutableStatus(), r.machineState, m_hostPanic);
        afterStatusRead();
    };
    steps << ht << enq;
    if (how.temperature) {
        ElabExchange etb = exchange(owner, encode::requestTemperature(), Expect::Temperature);
        etb.onReply = [this](const Reply& r) {
            ElabCtlStatusMapper::applyTemperature(mutableStatus(), r.temperature);
        };
        steps << etb;
    }
    if (how.startButton) {
        // RequestStart: <ACK> pressed, <NAK> not pressed -- a NAK here is an answer, not a fault.
        ElabExchange lf = exchange(owner, encode::requestStart(), Expect::AckNak);
        lf.onReply = [this](const Reply& r) {
            mutableStatus().startButton = r.kind == Reply::Kind::Ack;
        };
        steps << lf;
    }
    for (ElabExchange& ex : steps) {
        ex.poll = how.poll;
        ex.tolerateStray = how.tolerant;
        ex.droppable = !how.poll && owner != 0;
    }
    chain(
        steps, how.continuation,
        [this, done] {
            publishStatus();
            done();
        },
        failed);
}

void ElabController::sendCommand(const Op& op, const QByteArray& frame, std::function<void()> onAck,
                                 bool continuation)
{
    ElabExchange ex = exchange(op.id, frame, Expect::AckNak);
    ex.onReply = [this, op, frame, onAck](const Reply& r) {
        if (r.kind == Reply::Kind::Ack)
            onAck();
        else
            failWithNak(op, frame);
    };
    ex.onError = [this, op](ErrorKind kind, const QString& message) {
        finishError(op.id, kind, message);
    };
    if (continuation)
        m_queue.enqueueNext(std::move(ex));
    else
        m_queue.enqueue(std::move(ex));
}

void ElabController::failWithNak(const Op& op, const QByteArray& frame)
{
    // "Im Falle eines <NAK> ist es am besten man liest beide Status Informationen mit
    // RequestAxeState und RequestMachineState aus".
    const QString command = toMnemonics(frame);
    StatusRead how;
    how.continuation = true;
    readStatus(
        op.id, how,
        [this, op, command] {
            finishError(op.id, ErrorKind::Nak,
                        tr("%1 answered NAK; machine state %2: %3; axe state %4: %5")
                            .arg(command)
                            .arg(m_machineWord, 4, 16, QLatin1Char('0'))
                            .arg(describeMachineState(m_machineWord))
                            .arg(m_axeWord, 2, 16, QLatin1Char('0'))
                            .arg(describeAxeState(m_axeWord)));
        },
        [this, op, command](ErrorKind, const QString& why) {
            finishError(op.id, ErrorKind::Nak,
                        tr("%1 answered NAK; the status could not be read: %2").arg(command, why));
        });
}

void ElabController::preflight(RequestId id, ElabCtlStatusMapper::Rule rule,
                               std::function<void(Op)> then)
{
    // "Deshalb muss vor jedem Move Kommando solange mit RequestAxeState gepollt werden, bis der
    // letzte Befehl komplett ausgeführt ist ... Ausserdem darf das LimitSwitch Flag nicht aktiv
    // sein." The command follows the status read directly (continuation), so nothing else can
    // start in between.
    const Op op{id, m_epoch};
    readStatus(
        id, StatusRead{},
        [this, op, rule, then] {
            if (stale(op))
                return;
            const QString refusal = ElabCtlStatusMapper::refusal(rule, m_machineWord, m_axeWord);
            if (!refusal.isEmpty()) {
                finishError(op.id, ErrorKind::Refused, refusal);
                return;
            }
            then(op);
        },
        [this, id](ErrorKind kind, const QString& why) { finishError(id, kind, why); });
}

bool ElabController::stale(const Op& op)
{
    if (op.epoch == m_epoch)
        return false;
    finishError(op.id, ErrorKind::Cancelled, tr("cancelled by a stop, panic or reset"));
    return true;
}

bool ElabController::requireLink(RequestId id)
{
    if (linkState() == LinkState::Connected)
        return true;
    finishError(id, ErrorKind::LinkDown, tr("not connected (%1)").arg(linkStateName(linkState())));
    return false;
}

void ElabController::afterStatusRead()
{
    const AxisVector values = m_motion.values();
    const bool stoppedMove = m_motion.stopped();
    const ElabCtlMotion::Outcome out = m_motion.update(m_machineWord, m_axeWord);
    MachineStatus& s = mutableStatus();
    for (Axis a : out.lostAxes) {
        s.axes[a].referenced = false;
        s.axes[a].positionKnown = false;
    }
    for (Axis a : out.referencedAxes) {
        AxisStatus& axis = s.axes[a];
        axis.referenced = axis.positionKnown = true;
        axis.position = 0;
        axis.positionEstimated = false;
    }
    if (!out.limitMessage.isEmpty())
        Q_EMIT errorOccurred(out.limitMessage);
    if (out.readRemaining && stoppedMove)
        correctPositions(values);
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
    // Start clean: a half-received command of an earlier session is finished off by the
    // <SYN> burst (RequestSync), then the status words and the temperature are read.
    ElabExchange burst = exchange(0, encode::requestSync(16), Expect::None);
    burst.droppable = false;
    m_queue.enqueue(burst);
    StatusRead how;
    how.temperature = how.startButton = true;
    how.tolerant = true;
    readStatus(
        0, how,
        [this] {
            if (m_machineWord & machine::InvSetup)
                m_written.clear(); // the board lost its setup (power cycle): nothing is known
            m_hostPanic = false;
            ElabCtlStatusMapper::applyMachineState(mutableStatus(), m_machineWord, false);
            markAllUnreferenced();
            setLinkState(LinkState::Connected);
            m_poller.start();
            const RequestId id = std::exchange(m_openId, 0);
            finishOk(id);
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
    ++m_epoch;
    abortStream(kind, message);
    m_motion.clear();
    m_queue.failAll(kind, message);
    haltJogImmediately();
    m_jogMode = m_jogQueued = false;
}

void ElabController::linkDown(const QString& reason, bool closeTransport)
{
    if (linkState() == LinkState::Disconnected && m_openId == 0)
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
        (jogActive() || m_jogMode || m_motion.kind() == ElabCtlMotion::Kind::Velocity ||
         m_stream.isActive())) {
        // Best effort: nothing may keep running unattended (jog, velocity move, stream).
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
    if (linkState() != LinkState::Connected || !m_poller.isDue())
        return;
    m_poller.pollStarted();
    ++m_pollCount;
    StatusRead how;
    how.poll = true;
    how.temperature = m_pollCount % kTemperatureEveryNthPoll == 1;
    how.startButton = m_pollCount % kStartButtonEveryNthPoll == 0;
    readStatus(
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
    StatusRead how;
    how.temperature = how.startButton = true;
    readStatus(
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
    ElabExchange ex = exchange(id, bytes, expectFor(bytes));
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
    const bool streaming = m_stream.isActive();
    ++m_epoch;
    // Work not yet written is dropped; polls stay (they are harmless and keep the status).
    m_queue.dropQueued(ErrorKind::Cancelled, tr("cancelled by stop"), false);
    abortStream(ErrorKind::Cancelled, tr("feed stream stopped"));
    // "ForceStopMove stoppt sofort jegliche Bewegung mit Bremsrampen" -- jog included, so the
    // host ramp stops at once instead of fighting the board's brake ramp.
    haltJogImmediately();
    m_jogMode = m_jogQueued = false;
    const Op op{id, m_epoch};
    ElabExchange ex = exchange(id, encode::stopMove(), Expect::AckNak);
    ex.onReply = [this, op, streaming](const Reply& r) {
        if (r.kind != Reply::Kind::Ack) {
            failWithNak(op, encode::stopMove());
            return;
        }
        m_motion.markStopped(); // after the reply of what was in flight (FIFO)
        m_motion.endStream();
        if (!streaming) {
            finishOk(op.id);
            return;
        }
        // A stop during <DC2>: the buffer still holds single steps; flush it and end the feed
        // ("Der Buffer kann jetzt mit folgendem Kommando geleert werden": <GS>; "Den Abschluss
        // ... muss immer ein EndOfFeed Kommando sein").
        sendCommand(op, encode::flushBuffer(), [this, op] {
            sendCommand(op, encode::endOfFeed(), [this, op] { finishOk(op.id); });
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
    const bool streaming = m_stream.isActive();
    m_hostPanic = true;
    const QString why = tr("cancelled by panic stop");
    ++m_epoch;
    abortStream(ErrorKind::Cancelled, why);
    m_motion.clear();
    haltJogImmediately();
    m_jogMode = m_jogQueued = false;
    m_queue.dropQueued(ErrorKind::Cancelled, why, true);
    m_queue.abandonInFlight(ErrorKind::Cancelled, why);
    // "Beim Wiederanlauf muss das System neu initialisiert werden, da ... Schritte verloren
    // gehen."
    markAllUnreferenced();
    mutableStatus().panic = true;
    // Mid-stream the board may wait for the data byte of a <DC2> pair whose data byte was
    // discarded: a first <BEL> is then taken as the step byte 0x07 (no step bit set, harmless)
    // and the second one is the panic. Outside a stream the second <BEL> is a second panic.
    ElabExchange ex =
        exchange(id, streaming ? encode::panicStop() + encode::panicStop() : encode::panicStop(),
                 Expect::Ack);
    ex.tolerateStray = true; // replies of abandoned exchanges may still come
    ex.onReply = [this, id](const Reply&) {
        finishOk(id);
        StatusRead how;
        how.continuation = how.tolerant = true;
        readStatus(
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
    const quint64 epoch = m_epoch;
    QTimer::singleShot(kResetPulseMs, this, [this, id, epoch] {
        if (epoch != m_epoch || !transport())
            return; // link lost meanwhile: the request was already finished
        QString e;
        transport()->setResetLine(false, &e);
        QTimer::singleShot(kResetSettleMs, this, [this, id, epoch] {
            if (epoch != m_epoch)
                return;
            m_queue.setHeld(false);
            m_hostPanic = false;
            m_written.clear(); // a reset board has lost its setup
            StatusRead how;
            how.temperature = how.tolerant = true;
            readStatus(
                id, how,
                [this, id] {
                    m_poller.start();
                    finishOk(id);
                },
                [this, id](ErrorKind kind, const QString& why) {
                    m_poller.start();
                    finishError(id, kind, tr("no status after reset: %1").arg(why));
                });
        });
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
    writeStep(Op{id, m_epoch}, plan, 0, note);
}

void ElabController::writeStep(const Op& op, const QList<ElabParameterWrite>& plan, int index,
                               const QString& note)
{
    // One setup command after the other; a NAK stops the sequence (the rest is not sent).
    if (index == plan.size()) {
        finish(CommandResult{op.id, ErrorKind::None, note, {}});
        return;
    }
    const ElabParameterWrite& w = plan.at(index);
    sendCommand(
        op, w.frame,
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

} // namespace stepdeck::elab
