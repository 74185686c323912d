#pragma once
#include "EmisMotion.h"

namespace stepdeck::emis {

// Jog without a stop command: a chain of short relative vector moves (9.11), each covering at
// most kJogChunkSeconds of travel at the commanded rate. The next chunk goes out only after
// the previous one's <DCn> arrived and only while the jog lease holds, so a released jog ends
// with the chunk under way. Each chunk runs at the commanded rate by setting the axis' work
// speed (#E1); when the jog ends the work speed is set back (EmisWorkSpeeds).
class EmisJog
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    static constexpr double kJogChunkSeconds = 0.2;

    EmisJog(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
            EmisMotionTracker& tracker, EmisMotion& motion);

    // The ramp's complete output: an axis it no longer names has rate zero.
    void apply(const AxisVelocities& stepsPerS);
    QString refusal() const; // beyond the base's: why a jog cannot start now
    double rate(Axis axis) const { return m_jogRates.value(axis, 0.0); }
    bool sending() const { return m_sending; } // a chunk may be on its way
    // The chain ends here: no further chunk goes out (a chunk under way ends by itself).
    void end();
    // end(), and the host no longer waits for a chunk on its way (link lost, closed).
    void abort();

    // EmisMotion::Hooks and EmisMotionTracker::Hooks
    void onChunkSettled(bool ok, const QString& why);
    void onChunkArrived() { pump(); }
    void halt(const QString& reason);

private:
    void pump();
    void sendChunk(QList<EmisWorkSpeeds::Write> speedWrites, QList<VectorTarget> chunk);
    bool held(Axis axis, double direction) const; // the input still asks for this way
    // A jog chunk ends at the soft limit; 0 and *why at the limit.
    qint64 clipToSoftLimit(Axis axis, qint64 steps, QString* why) const;
    void finishIfIdle();

    EmisHost& m_host;
    EmisExchange& m_exchange;
    EmisKnownValues& m_known;
    const EmisMotionTracker& m_tracker;
    EmisMotion& m_motion;
    AxisVelocities m_jogRates; // the newest rates from the ramp
    QString m_softLimitSaid;   // the last jog refusal for a soft limit (said once)
    bool m_sending = false;    // a chunk (with its speed writes) is on its way
};

} // namespace stepdeck::emis
