#include "ElabCtlMotion.h"
#include "ElabCodec.h"
#include "ElabCtlStatusMapper.h"
#include <QCoreApplication>

namespace stepdeck::elab {

void ElabCtlMotion::start(Kind kind, const AxisVector& values)
{
    clear();
    m_kind = kind;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        if (it.value() != 0)
            m_values.insert(it.key(), it.value());
    }
}

ElabCtlMotion::Outcome ElabCtlMotion::update(quint16 machineState, quint8 axeState)
{
    using M = ElabCtlStatusMapper;
    Outcome out;
    if (m_kind == Kind::None)
        return out;
    bool anyNewLimit = false;
    for (Axis a : axes()) {
        if (M::referenceSwitch(machineState, a))
            m_sawReference.insert(a);
        if (M::limitSwitch(machineState, a) && !m_hitLimit.contains(a)) {
            m_hitLimit.insert(a);
            anyNewLimit = true;
        }
    }
    // taLimSw without an axis bit: the word does not say which axis; all of ours are suspect.
    if ((axeState & axe::LimSw) && m_hitLimit.isEmpty()) {
        for (Axis a : axes())
            m_hitLimit.insert(a);
        anyNewLimit = true;
    }
    if (anyNewLimit) {
        QStringList names;
        for (Axis a : m_hitLimit)
            names << axisName(a);
        names.sort();
        out.limitMessage = QCoreApplication::translate(
                               "stepdeck::elab::ElabController",
                               "a limit switch stopped the motion (axis %1): position unknown, "
                               "reference the axis again")
                               .arg(names.join(QLatin1Char(',')));
    }

    bool moving = false;
    for (Axis a : axes())
        moving = moving || M::axisMoving(axeState, a);
    const bool waitForHost = m_kind == Kind::Stream && !m_streamEnded;
    if (moving || waitForHost) {
        out.lostAxes = QList<Axis>(m_hitLimit.cbegin(), m_hitLimit.cend());
        return out;
    }

    out.finished = true;
    QSet<Axis> lost = m_hitLimit;
    switch (m_kind) {
    case Kind::FastMove:
    case Kind::Feed:
        // ForceStopMove: "ist diesem die noch verbleibenden Schritte des vorausgegangenen
        // FastMove Kommandos bekannt ... mit RequestRelPosition ... abfragen".
        out.readRemaining = m_stopped && lost.isEmpty();
        break;
    case Kind::Stream:
        // Steps flushed from the board's buffer after a stop were sent but never run, and no
        // reply says how many (ForceStopMove then ForceFlushBuffer: close, link loss, a limit
        // switch, a STOP whose contour did not end). A STOP during a contour ends the stream
        // without them (ElabCtlMotionOps::stopContour): not stopped here, every axis kept.
        if (m_stopped)
            lost.unite(QSet<Axis>(m_values.keyBegin(), m_values.keyEnd()));
        break;
    case Kind::Reference:
        for (Axis a : axes()) {
            if (!m_stopped && m_sawReference.contains(a) && !lost.contains(a))
                out.referencedAxes << a;
            else
                lost.insert(a);
        }
        break;
    case Kind::Velocity:
        // The board ramps on its own; the host cannot integrate the distance.
        lost.unite(QSet<Axis>(m_values.keyBegin(), m_values.keyEnd()));
        break;
    case Kind::None:
        break;
    }
    out.lostAxes = QList<Axis>(lost.cbegin(), lost.cend());
    std::sort(out.lostAxes.begin(), out.lostAxes.end());
    clear();
    return out;
}

} // namespace stepdeck::elab
