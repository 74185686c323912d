#include "EmisWorkSpeeds.h"
#include "EmisCodec.h"

namespace stepdeck::emis {

void EmisWorkSpeeds::setWritten(Axis axis, qint64 speed)
{
    m_written.insert(axis, speed);
    m_onBoard.insert(axis, speed);
}

void EmisWorkSpeeds::setStored(const QMap<Axis, qint64>& speeds)
{
    m_stored = speeds;
}

qint64 EmisWorkSpeeds::moveSpeed(Axis axis) const
{
    if (m_written.contains(axis))
        return m_written.value(axis);
    return m_stored.value(axis, kAssumedDefault);
}

std::optional<qint64> EmisWorkSpeeds::knownMoveSpeed(Axis axis) const
{
    if (m_written.contains(axis))
        return m_written.value(axis);
    if (m_stored.contains(axis))
        return m_stored.value(axis);
    return std::nullopt;
}

QList<EmisWorkSpeeds::Write> EmisWorkSpeeds::writesForMove(const QList<Axis>& axes) const
{
    QList<Write> out;
    for (Axis axis : emisAxes()) {
        if (!axes.contains(axis))
            continue;
        const qint64 speed = moveSpeed(axis);
        if (m_onBoard.value(axis, -1) != speed)
            out << Write{axis, speed};
    }
    return out;
}

QList<EmisWorkSpeeds::Write> EmisWorkSpeeds::writesToRestore() const
{
    QList<Write> out;
    for (auto it = m_onBoard.cbegin(); it != m_onBoard.cend(); ++it) {
        if (it.value() != moveSpeed(it.key()) && !m_writing.contains(it.key()))
            out << Write{it.key(), moveSpeed(it.key())};
    }
    return out;
}

bool EmisWorkSpeeds::jogNeedsWrite(Axis axis, qint64 speed) const
{
    if (!m_onBoard.contains(axis))
        return true;
    return qAbs(double(m_onBoard.value(axis) - speed)) > kJogTolerance * double(speed);
}

void EmisWorkSpeeds::noteOnBoard(Axis axis, qint64 speed)
{
    m_onBoard.insert(axis, speed);
    m_writing.remove(axis);
}

void EmisWorkSpeeds::forgetBoard(Axis axis)
{
    m_onBoard.remove(axis);
    m_writing.remove(axis);
}

void EmisWorkSpeeds::forgetBoard()
{
    m_onBoard.clear();
}

} // namespace stepdeck::emis
