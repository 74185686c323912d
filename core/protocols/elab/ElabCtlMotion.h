#pragma once
#include "model/Axis.h"
#include <QSet>

namespace stepdeck::elab {

// Host-side bookkeeping of the one motion the board runs (the manual allows no second one
// before standstill). The board never reports absolute positions, so the adapter learns from
// status reads when a motion ended and what that means for the positions it tracks. Pure.
class ElabCtlMotion
{
public:
    enum class Kind { None, FastMove, Feed, Stream, Reference, Velocity };

    struct Outcome
    {
        bool finished = false;
        bool readRemaining = false; // a ForceStopMove cut a FastMove/feed short: ask
                                    // RequestRelPosition for the steps not executed
        QList<Axis> lostAxes;       // position unknown from now on
        QList<Axis> referencedAxes; // reference run ended on the reference switch
        QString limitMessage;       // a limit switch stopped the motion (once)
    };

    // values: signed steps (FastMove, feed), directions (reference), rates (velocity); a
    // stream names its axes with any non-zero value.
    void start(Kind kind, const AxisVector& values);
    void clear() { *this = ElabCtlMotion(); }
    void markStopped() { m_stopped = true; }
    // A stream is finished by the host (EndOfFeed or a stop), not by the first idle status:
    // the board runs dry between chunks.
    void endStream() { m_streamEnded = true; }

    bool isActive() const { return m_kind != Kind::None; }
    Kind kind() const { return m_kind; }
    bool stopped() const { return m_stopped; }
    QList<Axis> axes() const { return m_values.keys(); }
    const AxisVector& values() const { return m_values; }

    // One complete status read (RequestMachineState and RequestAxeState).
    Outcome update(quint16 machineState, quint8 axeState);

private:
    Kind m_kind = Kind::None;
    AxisVector m_values;
    QSet<Axis> m_sawReference;
    QSet<Axis> m_hitLimit;
    bool m_stopped = false;
    bool m_streamEnded = false;
};

} // namespace stepdeck::elab
