#pragma once
#include "model/Axis.h"
#include <QList>
#include <QMap>
#include <QSet>

namespace stepdeck::emis {

// The work speed of vector moves (#E1, 9.5) per axis, as far as the host knows it. The SMC-IC4
// cannot report its working values, jog chunks run at the jog rate by changing the work speed,
// and a reset (5.8), an input program (9.17), another program or an earlier session that ended
// in the middle of a jog may change it behind the host's back. So two things are kept apart:
// - the move speed, which every positioning move runs at: written in this session (set, the
//   console's #E1), else the stored power-on value (*PRSYS, ##E), else kAssumedDefault;
// - the speed the board has: only what it acknowledged in this session, and forgotten whenever
//   it may have changed behind the host's back (a new session, a request without an answer, an
//   arrival that never came or that nobody awaited, a write the board did not take).
// Before a move, every axis whose board speed is not known to be its move speed gets an #E1
// write (writesForMove), so no move runs at a speed the host does not know. Pure: no I/O.
class EmisWorkSpeeds
{
public:
    // 9.5 shows "#E1,1000"; the manual names no power-on work speed for a board with nothing
    // stored. StepDeck assumes this one (the schema's default) when it knows no other.
    static constexpr qint64 kAssumedDefault = 1000;
    // A jog speed within this fraction of the board's speed is not rewritten.
    static constexpr double kJogTolerance = 0.1;
    struct Write
    {
        Axis axis = Axis::X;
        qint64 speed = 0;
    };

    void setWritten(Axis axis, qint64 speed);         // set or console #E1 the board acknowledged
    void setStored(const QMap<Axis, qint64>& speeds); // the power-on values (*PRSYS, ##E)
    qint64 moveSpeed(Axis axis) const;
    // The move speed where it is known (written in this session, or stored), not assumed.
    std::optional<qint64> knownMoveSpeed(Axis axis) const;
    // The #E1 writes a move of `axes` needs first, in X, Y, Z, U order.
    QList<Write> writesForMove(const QList<Axis>& axes) const;
    // After a jog: the axes whose known board speed is not their move speed (and that have no
    // write on its way).
    QList<Write> writesToRestore() const;
    // A jog chunk at `speed` needs an #E1 first: the board's speed is not known to be near it.
    bool jogNeedsWrite(Axis axis, qint64 speed) const;

    void noteWriting(Axis axis) { m_writing.insert(axis); } // an #E1 is on its way
    void noteOnBoard(Axis axis, qint64 speed);              // the board acknowledged it
    void forgetBoard(Axis axis);                            // it did not, or may have changed
    void forgetBoard();                                     // every axis

private:
    QMap<Axis, qint64> m_written;
    QMap<Axis, qint64> m_stored;
    QMap<Axis, qint64> m_onBoard;
    QSet<Axis> m_writing;
};

} // namespace stepdeck::emis
