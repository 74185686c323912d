#include "ElabCtlMotionOps.h"
#include "Logging.h"
#include <QCoreApplication>
#include <QTimer>
#include <limits>
#include <memory>
#include <utility>

namespace stepdeck::elab {

using Rule = ElabCtlStatusMapper::Rule;
using Op = ElabCtlLine::Op;

namespace {
template <typename T> Triple<T> toTriple(const AxisVector& values)
{
    Triple<T> t{};
    for (Axis a : ElabCtlStatusMapper::axes())
        t[wireIndex(a)] = T(values.value(a));
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

constexpr int kReversalPollMs = 50;
constexpr qint64 kReversalWaitMs = 10000; // a braking ramp far longer than this is a fault
constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();
constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kInt16Min = std::numeric_limits<qint16>::min();
constexpr qint64 kInt16Max = std::numeric_limits<qint16>::max();
} // namespace

bool ElabCtlMotionOps::checkAxes(RequestId id, const AxisVector& values, qint64 minimum,
                                 qint64 maximum, const QString& what)
{
    // Every value against its wire type; nothing is sent otherwise.
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        QString error;
        if (!ElabCtlStatusMapper::axes().contains(it.key()))
            error = tr("this machine has no axis %1").arg(axisName(it.key()));
        else if (it.value() < minimum || it.value() > maximum)
            error = tr("%1 %2 for axis %3 is out of range (allowed: %4..%5)")
                        .arg(what)
                        .arg(it.value())
                        .arg(axisName(it.key()))
                        .arg(minimum)
                        .arg(maximum);
        if (!error.isEmpty()) {
            m_line.hooks().fail(id, ErrorKind::InvalidValue, error);
            return false;
        }
    }
    return m_line.hooks().requireLink(id);
}

void ElabCtlMotionOps::accepted(ElabCtlMotion::Kind kind, const AxisVector& values)
{
    using K = ElabCtlMotion::Kind;
    m_motion.start(kind, values);
    if (kind == K::Velocity) {
        for (auto it = values.cbegin(); it != values.cend(); ++it) {
            if (it.value() != 0)
                m_velocitySign.insert(it.key(), it.value() > 0 ? 1 : -1);
        }
    }
    m_line.setHostPanic(false); // the operator has started again after a panic
    for (auto it = m_motion.values().cbegin(); it != m_motion.values().cend(); ++it) {
        AxisStatus& axis = m_line.status().axes[it.key()];
        axis.moving = true;
        if (kind == K::FastMove || kind == K::Feed)
            axis.position += it.value(); // relative steps; corrected after a stop
        else if (kind == K::Reference || kind == K::Velocity)
            axis.referenced = axis.positionKnown = false;
    }
    m_line.hooks().publish();
}

void ElabCtlMotionOps::onStatusRead()
{
    for (Axis a : m_velocitySign.keys()) {
        if (!ElabCtlStatusMapper::axisMoving(m_line.axeWord(), a))
            m_velocitySign.remove(a);
    }
    const AxisVector values = m_motion.values();
    const ElabCtlMotion::Outcome out = m_motion.update(m_line.machineWord(), m_line.axeWord());
    if (!out.limitMessage.isEmpty() && m_stream.isActive()) {
        // A limit switch ends a <DC2> stream at once ("Wenn eine Fahrt einen Endschalter
        // erreicht hat, dann wird diese auch immer sofort abgebrochen"): no more steps, the
        // board's buffer flushed and the feed ended.
        abortStream(ErrorKind::Refused, out.limitMessage);
        const ElabCtlLine::Op internal = m_line.op(0);
        m_line.sendCommand(internal, encode::flushBuffer(), [this, internal] {
            m_line.sendCommand(internal, encode::endOfFeed(), [] {});
        });
    }
    MachineStatus& s = m_line.status();
    for (Axis a : out.lostAxes)
        s.axes[a].referenced = s.axes[a].positionKnown = false;
    for (Axis a : out.referencedAxes) {
        AxisStatus& axis = s.axes[a];
        axis.referenced = axis.positionKnown = true;
        axis.position = 0;
        axis.positionEstimated = false;
    }
    if (!out.limitMessage.isEmpty())
        m_line.hooks().error(out.limitMessage);
    if (out.readRemaining)
        correctPositions(values);
    showHeldAtRest();
}

void ElabCtlMotionOps::onStopAccepted()
{
    m_motion.markStopped();
    m_motion.endStream();
}

void ElabCtlMotionOps::correctPositions(const AxisVector& stopped)
{
    // ForceStopMove: "Dann kann er mit RequestRelPosition die jeweils noch verbleibenden
    // Schritte abfragen" -- the signed steps of the interrupted move that were not executed.
    // Until the answer the count is the interrupted move's target, not where the board stands:
    // estimated, so that no absolute move is computed from it (Machine::move refuses one; a
    // move computed from it once landed the whole remainder short, tst_machinestop).
    for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
        m_line.status().axes[it.key()].positionEstimated = true;
    ElabExchange etx = ElabCtlLine::exchange(0, encode::requestRelPosition(), Expect::RelPosition);
    etx.droppable = false;
    etx.onReply = [this, stopped](const Reply& r) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it) {
            AxisStatus& axis = m_line.status().axes[it.key()];
            axis.position -= r.positions[wireIndex(it.key())];
            axis.positionEstimated = false;
        }
        m_line.hooks().publish();
    };
    etx.onError = [this, stopped](ErrorKind, const QString& why) {
        for (auto it = stopped.cbegin(); it != stopped.cend(); ++it)
            m_line.status().axes[it.key()].positionKnown = false;
        m_line.hooks().error(tr("position after stop unknown: %1").arg(why));
        m_line.hooks().publish();
    };
    m_line.submit(std::move(etx), true);
}

std::optional<AxisVector> ElabCtlMotionOps::stepsToSend(RequestId id, const AxisVector& steps)
{
    // Signed 32-bit step counts (manual: "Die Werte sind 32bit Integer"); an all-zero move has
    // nothing to send and succeeds at once.
    if (!checkAxes(id, steps, kInt32Min, kInt32Max, tr("step count")))
        return std::nullopt;
    const AxisVector move = nonZero(steps);
    if (move.isEmpty()) {
        m_line.hooks().ok(id, {});
        return std::nullopt;
    }
    return move;
}

void ElabCtlMotionOps::moveRelative(RequestId id, const AxisVector& steps)
{
    const std::optional<AxisVector> checked = stepsToSend(id, steps);
    if (!checked)
        return;
    const AxisVector& move = *checked;
    // The narrowest command: SetFastMoveZ <BS>, SetFastMoveXY <FF>, else SetFastMoveXYZ <EOT>.
    QByteArray frame;
    if (!move.contains(Axis::X) && !move.contains(Axis::Y))
        frame = encode::fastMoveZ(qint32(move.value(Axis::Z)));
    else if (!move.contains(Axis::Z))
        frame = encode::fastMoveXY(qint32(move.value(Axis::X)), qint32(move.value(Axis::Y)));
    else
        frame = encode::fastMoveXYZ(toTriple<qint32>(move));
    m_line.preflight(id, Rule::Move, [this, frame, move](Op op) {
        m_line.sendCommand(op, frame, [this, op, move] {
            accepted(ElabCtlMotion::Kind::FastMove, move);
            m_line.hooks().ok(op.id, {});
        });
    });
}

void ElabCtlMotionOps::feed(RequestId id, const AxisVector& steps)
{
    const std::optional<AxisVector> checked = stepsToSend(id, steps);
    if (!checked)
        return;
    const AxisVector& move = *checked;
    if (move.size() > 1) {
        startStream(id, {}, toTriple<qint64>(move));
        return;
    }
    const Axis axis = move.firstKey();
    const qint32 n = qint32(move.first());
    const QByteArray frame = axis == Axis::X   ? encode::feedStepsX(n)
                             : axis == Axis::Y ? encode::feedStepsY(n)
                                               : encode::feedStepsZ(n);
    m_line.preflight(id, Rule::Move, [this, frame, move](Op op) {
        // SetClearPosition: "Dieser Befehl sollte vor jedem Befehl im Feedmodus aufgerufen
        // werden."
        m_line.sendCommand(op, encode::clearPosition(), [this, op, frame, move] {
            if (m_line.stale(op))
                return;
            m_line.sendCommand(op, frame, [this, op, move] {
                accepted(ElabCtlMotion::Kind::Feed, move);
                m_line.hooks().ok(op.id, {});
            });
        });
    });
}

void ElabCtlMotionOps::reference(RequestId id, const AxisVector& directions)
{
    // SetReferenceMoveXYZ: "Die Werte sind 16bit Integer (-1/0/+1)".
    if (!checkAxes(id, directions, -1, 1, tr("reference direction")))
        return;
    const AxisVector run = nonZero(directions);
    if (run.isEmpty()) {
        m_line.hooks().ok(id, {});
        return;
    }
    m_line.preflight(id, Rule::Move, [this, run](Op op) {
        m_line.sendCommand(op, encode::referenceMove(toTriple<qint16>(run)), [this, op, run] {
            accepted(ElabCtlMotion::Kind::Reference, run);
            m_line.hooks().ok(op.id, {});
        });
    });
}

void ElabCtlMotionOps::velocityMove(RequestId id, const AxisVector& stepsPerS)
{
    if (!checkAxes(id, stepsPerS, kInt16Min, kInt16Max, tr("velocity")))
        return;
    const bool running = velocityRunning();
    AxisVector rates = running ? m_motion.values() : AxisVector();
    QList<Axis> reversing;
    for (auto it = stepsPerS.cbegin(); it != stepsPerS.cend(); ++it) {
        const qint64 before = rates.value(it.key());
        if (before != 0 && it.value() != 0 && (before > 0) != (it.value() > 0)) {
            // "Eine Drehrichtungs Umkehr ist bei laufendem Motor hier nicht möglich."
            m_line.hooks().fail(id, ErrorKind::Refused,
                                tr("refused: axis %1 cannot reverse during a velocity move; set "
                                   "it to 0 and wait for standstill first")
                                    .arg(axisName(it.key())));
            return;
        }
        // Commanded 0 but maybe still braking: the new sign waits for its standstill.
        const int lastSign = m_velocitySign.value(it.key(), 0);
        if (before == 0 && it.value() != 0 && lastSign != 0 && (it.value() > 0) != (lastSign > 0))
            reversing << it.key();
        rates.insert(it.key(), it.value());
    }
    if (!running && nonZero(rates).isEmpty()) {
        m_line.hooks().ok(id, {});
        return;
    }
    sendVelocity(id, rates, running, reversing, m_clock.elapsed() + kReversalWaitMs,
                 m_line.epoch());
}

void ElabCtlMotionOps::sendVelocity(RequestId id, const AxisVector& rates, bool running,
                                    const QList<Axis>& reversing, qint64 deadlineMs, quint64 epoch)
{
    if (epoch != m_line.epoch()) {
        m_line.hooks().fail(id, ErrorKind::Cancelled, tr("cancelled by a stop, panic or reset"));
        return;
    }
    // The first VelocityMove needs standstill; later ones only change the rates, except for an
    // axis that reverses: "dann muss gewartet werden, bis diese Achse zum Stillstand gekommen
    // ist (pollen des Achsen Status)".
    m_line.preflight(
        id, running ? Rule::VelocityUpdate : Rule::Move,
        [this, rates, running, reversing, deadlineMs](Op op) {
            for (Axis a : reversing) {
                if (!ElabCtlStatusMapper::axisMoving(m_line.axeWord(), a))
                    continue;
                if (m_clock.elapsed() > deadlineMs) {
                    m_line.hooks().fail(op.id, ErrorKind::Timeout,
                                        tr("axis %1 did not come to a standstill; the reversed "
                                           "velocity was not sent")
                                            .arg(axisName(a)));
                    return;
                }
                QTimer::singleShot(kReversalPollMs, &m_line.queue(), [=] {
                    sendVelocity(op.id, rates, running, reversing, deadlineMs, op.epoch);
                });
                return;
            }
            const QByteArray frame = encode::velocityMove(toTriple<qint16>(rates));
            m_line.sendCommand(op, frame, [this, op, rates] {
                accepted(ElabCtlMotion::Kind::Velocity, rates);
                m_line.hooks().ok(op.id, {});
            });
        });
}

} // namespace stepdeck::elab
