// Motion, jog and auxiliary commands of ElabController (manual sections "Befehle zur
// Positionierung", "Befehle im Arbeitsmodus", "Befehle im Jogbetrieb", "Befehle zur einfachen
// Achsen Bewegung", "Hilfs Funktionen").
#include "ElabController.h"
#include "Logging.h"
#include <limits>

namespace stepdeck::elab {

using Rule = ElabCtlStatusMapper::Rule;

namespace {
template <typename T> Triple<T> triple(const AxisVector& values)
{
    Triple<T> t{};
    for (Axis a : ElabCtlStatusMapper::axes())
        t[size_t(a)] = T(values.value(a));
    return t;
}

AxisVector nonZero(const AxisVector& values)
{
    AxisVector out;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (it.value() != 0)
            out.insert(it.key(), it.value());
    }
    return out;
}
} // namespace

QString ElabController::checkAxes(const AxisVector& values, qint64 minimum, qint64 maximum,
                                  const QString& what) const
{
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (!ElabCtlStatusMapper::axes().contains(it.key()))
            return tr("this machine has no axis %1").arg(axisName(it.key()));
        if (it.value() < minimum || it.value() > maximum)
            return tr("%1 %2 for axis %3 is out of range (allowed: %4..%5)")
                .arg(what)
                .arg(it.value())
                .arg(axisName(it.key()))
                .arg(minimum)
                .arg(maximum);
    }
    return {};
}

void ElabController::motionAccepted(ElabCtlMotion::Kind kind, const AxisVector& values)
{
    using K = ElabCtlMotion::Kind;
    m_motion.start(kind, values);
    m_hostPanic = false; // the operator has started again after a panic
    mutableStatus().panic = (m_machineWord & machine::PanicStop) != 0;
    for (auto it = m_motion.values().cbegin(); it != m_motion.values().cend(); ++it) {
        AxisStatus& axis = mutableStatus().axes[it.key()];
        axis.moving = true;
        if (kind == K::FastMove || kind == K::Feed) {
            axis.position += it.value(); // relative steps; corrected after a stop
        } else if (kind == K::Reference || kind == K::Velocity) {
            axis.referenced = axis.positionKnown = false;
        }
    }
    publishStatus();
}

void ElabController::correctPositions(const AxisVector& stopped)
{
    // RequestRelPosition after ForceStopMove: the signed steps of the interrupted move that were
    // not executed.
    ElabExchange etx = exchange(0, encode::requestRelPosition(), Expect::RelPosition);
    etx.droppable = false;
    etx.onReply = [this, stopped](const Reply& r) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
            mutableStatus().axes[it.key()].position -= r.positions[size_t(it.key())];
        publishStatus();
    };
    etx.onError = [this, stopped](ErrorKind, const QString& why) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
            mutableStatus().axes[it.key()].positionKnown = false;
        Q_EMIT errorOccurred(tr("position after stop unknown: %1").arg(why));
        publishStatus();
    };
    m_queue.enqueueNext(std::move(etx));
}

void ElabController::moveRelative(RequestId id, const AxisVector& steps)
{
    const QString invalid = checkAxes(steps, std::numeric_limits<qint32>::min(),
                                      std::numeric_limits<qint32>::max(), tr("step count"));
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    const AxisVector move = nonZero(steps);
    if (move.isEmpty()) {
        finishOk(id);
        return;
    }
    // The narrowest command: SetFastMoveZ <BS>, SetFastMoveXY <FF>, else SetFastMoveXYZ <EOT>.
    QByteArray frame;
    if (!move.contains(Axis::X) && !move.contains(Axis::Y))
        frame = encode::fastMoveZ(qint32(move.value(Axis::Z)));
    else if (!move.contains(Axis::Z))
        frame = encode::fastMoveXY(qint32(move.value(Axis::X)), qint32(move.value(Axis::Y)));
    else
        frame = encode::fastMoveXYZ(triple<qint32>(move));
    preflight(id, Rule::Move, [this, frame, move](Op op) {
        sendCommand(op, frame, [this, op, move] {
            motionAccepted(ElabCtlMotion::Kind::FastMove, move);
            finishOk(op.id);
        });
    });
}

void ElabController::feed(RequestId id, const AxisVector& steps)
{
    const QString invalid = checkAxes(steps, std::numeric_limits<qint32>::min(),
                                      std::numeric_limits<qint32>::max(), tr("step count"));
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    const AxisVector move = nonZero(steps);
    if (move.isEmpty()) {
        finishOk(id);
        return;
    }
    if (move.size() > 1) {
        // SetFeedSteps X/Y/Z move one axis each; a line over several axes is a <DC2> stream.
        startStream(id, {}, triple<qint64>(move));
        return;
    }
    const Axis axis = move.firstKey();
    const qint32 n = qint32(move.first());
    const QByteArray frame = axis == Axis::X   ? encode::feedStepsX(n)
                             : axis == Axis::Y ? encode::feedStepsY(n)
                                               : encode::feedStepsZ(n);
    preflight(id, Rule::Move, [this, frame, move](Op op) {
        // SetClearPosition: "Dieser Befehl sollte vor jedem Befehl im Feedmodus aufgerufen
        // werden."
        sendCommand(op, encode::clearPosition(), [this, op, frame, move] {
            if (stale(op))
                return;
            sendCommand(op, frame, [this, op, move] {
                motionAccepted(ElabCtlMotion::Kind::Feed, move);
                finishOk(op.id);
            });
        });
    });
}

void ElabController::feedStream(RequestId id, const QVector<AxisVector>& steps)
{
    const QString invalid = ElabCtlStream::validate(steps);
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    if (steps.isEmpty()) {
        finishOk(id, 0);
        return;
    }
    startStream(id, steps, {});
}

void ElabController::startStream(RequestId id, const QVector<AxisVector>& steps,
                                 const Triple<qint64>& line)
{
    if (m_stream.isActive()) {
        finishError(id, ErrorKind::Refused, tr("refused: a feed stream is already running"));
        return;
    }
    // "Hier muss nur vor dem ersten Kommando die Abfrage erfolgen": one pre-flight, then <RS>.
    preflight(id, Rule::Move, [this, steps, line](Op op) {
        if (m_stream.isActive()) {
            finishError(op.id, ErrorKind::Refused, tr("refused: a feed stream is already running"));
            return;
        }
        sendCommand(op, encode::clearPosition(), [this, op, steps, line] {
            if (stale(op))
                return;
            if (steps.isEmpty())
                m_stream.startLine(line);
            else
                m_stream.startSteps(steps);
            m_stream.requestId = op.id;
            AxisVector axes;
            for (Axis a : m_stream.axes())
                axes.insert(a, 1);
            motionAccepted(ElabCtlMotion::Kind::Stream, axes);
            pumpStream();
        });
    });
}

void ElabController::pumpStream()
{
    if (!m_stream.isActive() || m_stream.chunkInFlight || m_stream.pausedByDevice)
        return;
    const RequestId id = m_stream.requestId;
    if (m_stream.atEnd()) {
        m_stream.chunkInFlight = true; // nothing more until EndOfFeed is answered
        ElabExchange end = exchange(id, encode::endOfFeed(), Expect::AckNak);
        end.onReply = [this, id](const Reply& r) {
            const qint64 sent = m_stream.sent();
            m_stream.clear();
            m_motion.endStream();
            if (r.kind == Reply::Kind::Ack)
                finishOk(id, sent);
            else
                failWithNak(Op{id, m_epoch}, encode::endOfFeed());
        };
        end.onError = [this](ErrorKind kind, const QString& why) { abortStream(kind, why); };
        m_queue.enqueue(std::move(end));
        return;
    }
    // At most one small chunk inside the transport: the next one is written when this one has
    // left, and only while the board has not said XOFF. Polls queue up between chunks.
    Triple<qint64> delta{};
    ElabExchange ex =
        exchange(id, m_stream.nextChunk(ElabCtlStream::kChunkSteps, &delta), Expect::None);
    m_stream.chunkInFlight = true;
    ex.onReply = [this, delta](const Reply&) {
        for (Axis a : ElabCtlStatusMapper::axes())
            mutableStatus().axes[a].position += delta[size_t(a)];
        m_stream.chunkInFlight = false;
        pumpStream();
    };
    ex.onError = [this](ErrorKind kind, const QString& why) {
        m_stream.chunkInFlight = false;
        abortStream(kind, why);
    };
    m_queue.enqueue(std::move(ex));
}

void ElabController::abortStream(ErrorKind kind, const QString& message)
{
    if (!m_stream.isActive())
        return;
    const RequestId id = m_stream.requestId;
    const QString text =
        tr("%1 after %2 of %3 steps").arg(message).arg(m_stream.sent()).arg(m_stream.total());
    m_stream.clear();
    m_motion.markStopped();
    m_motion.endStream();
    finishError(id, kind, text);
}

void ElabController::reference(RequestId id, const QMap<Axis, int>& directions)
{
    AxisVector dirs;
    for (auto it = directions.cbegin(); it != directions.cend(); ++it)
        dirs.insert(it.key(), it.value());
    // SetReferenceMoveXYZ: "Die Werte sind 16bit Integer (-1/0/+1)".
    const QString invalid = checkAxes(dirs, -1, 1, tr("reference direction"));
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    const AxisVector run = nonZero(dirs);
    if (run.isEmpty()) {
        finishOk(id);
        return;
    }
    preflight(id, Rule::Move, [this, run](Op op) {
        sendCommand(op, encode::referenceMove(triple<qint16>(run)), [this, op, run] {
            motionAccepted(ElabCtlMotion::Kind::Reference, run);
            finishOk(op.id);
        });
    });
}

void ElabController::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    const QString invalid = checkAxes(stepsPerS, std::numeric_limits<qint16>::min(),
                                      std::numeric_limits<qint16>::max(), tr("velocity"));
    if (!invalid.isEmpty()) {
        finishError(id, ErrorKind::InvalidValue, invalid);
        return;
    }
    if (!requireLink(id))
        return;
    const bool running = m_motion.kind() == ElabCtlMotion::Kind::Velocity;
    AxisVector rates = running ? m_motion.values() : AxisVector();
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        const qint64 before = rates.value(it.key());
        if (running && before != 0 && it.value() != 0 && (before > 0) != (it.value() > 0)) {
            // "Eine Drehrichtungs Umkehr ist bei laufendem Motor hier nicht möglich."
            finishError(id, ErrorKind::Refused,
                        tr("refused: axis %1 cannot reverse during a velocity move; set it to 0 "
                           "and wait for standstill first")
                            .arg(axisName(it.key())));
            return;
        }
        rates.insert(it.key(), it.value());
    }
    if (!running && nonZero(rates).isEmpty()) {
        finishOk(id);
        return;
    }
    // The first VelocityMove needs standstill; later ones only change the rates.
    preflight(id, running ? Rule::VelocityUpdate : Rule::Move, [this, rates](Op op) {
        sendCommand(op, encode::velocityMove(triple<qint16>(rates)), [this, op, rates] {
            motionAccepted(ElabCtlMotion::Kind::Velocity, rates);
            finishOk(op.id);
        });
    });
}

// ------------------------------------------------------------------ jog

QString ElabController::jogRefusal() const
{
    const QString base = Controller::jogRefusal();
    if (!base.isEmpty())
        return base;
    if (status().setupIncomplete)
        return tr("jog refused: setup incomplete (tmInvSetup): write start-speed, max-speed and "
                  "acceleration first");
    if (m_stream.isActive())
        return tr("jog refused: a feed stream is running");
    return {};
}

void ElabController::applyJogVelocity(const AxisVelocities& stepsPerS)
{
    // SetJogSpeed: "Die Werte sind 16bit Integer mit Vorzeichen."
    for (Axis a : ElabCtlStatusMapper::axes()) {
        const double v = qBound(double(std::numeric_limits<qint16>::min()), stepsPerS.value(a),
                                double(std::numeric_limits<qint16>::max()));
        m_jogRates[size_t(a)] = qint16(qRound(v));
    }
    if (m_jogQueued || linkState() != LinkState::Connected)
        return; // the queued <DC4> picks the newest rates up when it is written
    m_jogQueued = true;
    const bool moving = m_jogRates != Triple<qint16>{};
    if (m_jogMode || !moving) {
        sendJog(false);
        return;
    }
    // "muss vor dem ersten Jog-Kommando solange mit RequestAxeState gepollt werden, bis der
    // letzte Befehl komplett ausgeführt ist" -- jog stays allowed on an active limit switch.
    const quint64 epoch = m_epoch;
    readStatus(
        0, StatusRead{},
        [this, epoch] {
            if (epoch != m_epoch)
                return;
            const QString refusal =
                ElabCtlStatusMapper::refusal(Rule::FirstJog, m_machineWord, m_axeWord);
            if (refusal.isEmpty()) {
                sendJog(true);
                return;
            }
            m_jogQueued = false;
            haltJogImmediately();
            publishStatus();
            Q_EMIT jogRefused(refusal);
        },
        [this](ErrorKind, const QString& why) {
            m_jogQueued = false;
            haltJogImmediately();
            Q_EMIT jogRefused(tr("jog refused: %1").arg(why));
        });
}

void ElabController::sendJog(bool continuation)
{
    ElabExchange ex = exchange(0, {}, Expect::AckNak);
    ex.build = [this] {
        m_jogQueued = false; // from now on a new rate needs a new <DC4>
        m_jogSent = m_jogRates;
        return encode::jogSpeed(m_jogRates);
    };
    ex.onReply = [this](const Reply& r) {
        if (r.kind == Reply::Kind::Ack) {
            // "Der Modus wird automatisch wieder verlassen, wenn alle 3 Achsen eine Steprate
            // mit dem Wert 0 erhalten."
            m_jogMode = m_jogSent != Triple<qint16>{};
            return;
        }
        // "kann ein JOG Befehl mit einem <NAK> zurückkehren, wenn der Not-Aus manuell am
        // Controller betätigt wurde": stop the ramp and say why.
        haltJogImmediately();
        m_jogMode = false;
        StatusRead how;
        how.continuation = true;
        readStatus(
            0, how,
            [this] {
                const QString why =
                    tr("jog refused by the board (NAK); machine state: %1; axe "
                       "state: %2")
                        .arg(describeMachineState(m_machineWord), describeAxeState(m_axeWord));
                Q_EMIT errorOccurred(why);
                Q_EMIT jogRefused(why);
            },
            [](ErrorKind, const QString&) {});
    };
    ex.onError = [this](ErrorKind kind, const QString& why) {
        m_jogQueued = false;
        if (kind == ErrorKind::Cancelled)
            return;
        haltJogImmediately();
        m_jogMode = false;
        Q_EMIT errorOccurred(tr("jog: %1").arg(why));
    };
    if (continuation)
        m_queue.enqueueNext(std::move(ex));
    else
        m_queue.enqueue(std::move(ex));
}

// ------------------------------------------------------------------ auxiliaries

void ElabController::setSpindle(RequestId id, int rpm)
{
    // SetSpindleRPM: "einen Wert zwischen 0 und 1000 in einem long Hex-Word".
    if (rpm < 0 || rpm > 1000) {
        finishError(id, ErrorKind::InvalidValue,
                    tr("spindle-rpm: value '%1' is out of range (allowed: 0..1000 rpm)").arg(rpm));
        return;
    }
    if (!requireLink(id))
        return;
    sendCommand(
        Op{id, m_epoch}, encode::spindleRpm(quint32(rpm)),
        [this, id, rpm] {
            m_written.insert(QStringLiteral("spindle-rpm"), ParameterValue{qint64(rpm), {}});
            finishOk(id);
        },
        false);
}

void ElabController::setCoolant(RequestId id, bool on)
{
    if (!requireLink(id))
        return;
    sendCommand(
        Op{id, m_epoch}, encode::coolant(on),
        [this, id, on] {
            m_written.insert(QStringLiteral("coolant"), ParameterValue{on, {}});
            finishOk(id);
        },
        false);
}

void ElabController::setDrivePower(RequestId id, int percent)
{
    // SetDrivePower: "einen Wert zwischen 0 und 100 in einem Hex-Byte".
    if (percent < 0 || percent > 100) {
        finishError(id, ErrorKind::InvalidValue,
                    tr("drive-power: value '%1' is out of range (allowed: 0..100 %)").arg(percent));
        return;
    }
    if (!requireLink(id))
        return;
    sendCommand(
        Op{id, m_epoch}, encode::drivePower(quint8(percent)),
        [this, id, percent] {
            m_written.insert(QStringLiteral("drive-power"), ParameterValue{qint64(percent), {}});
            finishOk(id);
        },
        false);
}

} // namespace stepdeck::elab
