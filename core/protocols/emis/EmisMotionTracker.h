#pragma once
#include "EmisHost.h"
#include <QElapsedTimer>
#include <QTimer>

namespace stepdeck::emis {

// What the host knows of the SMC-IC4's motion, which it can only learn from the replies to its
// moves (the board reports neither positions nor status): "moving" is the time between <NAK>
// and <DCn>; positions are the sum of the arrived moves (absolute after a reference run). An
// arrival that does not come within its deadline, or a link lost while moves run, makes the
// axis unconfirmed with an unknown position until it is referenced again.
class EmisMotionTracker
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    struct Track
    {
        qint64 position = 0;     // sum of the arrived moves (known after a reference run)
        bool referenced = false; // in this session, and nothing lost since
        bool lost = false;       // a move's arrival never came: position unknown
        bool awaiting = false;   // <NAK> seen, <DCn> not yet
        bool overdue = false;    // awaiting past its deadline
        bool reference = false;  // the awaited motion is a reference run
        bool jogChunk = false;   // the awaited motion is a jog chunk
        // The host stopped waiting for this axis' arrival (deadline passed, link lost, no
        // reply to the move): it may still be moving. Cleared by its next <DCn>.
        bool unconfirmed = false;
        bool startPending = false;       // its move is on the line, <NAK> not yet seen
        bool arrivedBeforeStart = false; // <DCn> came while the <NAK> was still missing
        // Before an awaited arrival was declared lost: restored when it comes after all.
        bool lostBefore = false;
        bool referencedBefore = false;
        qint64 pendingSteps = 0; // relative distance of the awaited move
        qint64 deadlineMs = 0;
    };
    struct Hooks // the jog chain (EmisJog) hears of its chunks
    {
        std::function<void()> chunkArrived;                // a jog chunk's <DCn> came
        std::function<void(const QString& why)> chunkLost; // its arrival did not come in time
    };

    EmisMotionTracker(EmisHost& host, EmisKnownValues& known, QObject* owner, Hooks hooks);

    // A move of `axis` is on the line; settleStart() says what its reply was (a reference run
    // or a jog chunk, its relative distance, when its arrival is due), settled() after them.
    void markStartPending(Axis axis) { m_tracks[axis].startPending = true; }
    void settleStart(Axis axis, const EmisLink::Result& r, bool reference, bool jog, qint64 steps,
                     qint64 deadlineMs);
    void settled(); // deadlines re-armed, motionUnconfirmed brought up to date
    void onArrived(Axis axis);
    // The board may have been reset (5.8): its position counters start at 0 (absolute targets
    // mean something else, so no axis counts as referenced), its outputs are off and its work
    // speeds are the stored ones.
    void suspectReset();

    // A new session: positions count from here, nothing referenced.
    void startSession();
    void forgetReferences(); // the link is (re)connecting or lost
    // The host stops waiting (link lost, closed): every awaited axis becomes unconfirmed with
    // an unknown position.
    void stopTracking(const QString& reason);

    bool anyAwaiting() const;
    bool mayBeRunning() const; // awaited, on the line, or unconfirmed
    const QMap<Axis, Track>& tracks() const { return m_tracks; }
    qint64 position(Axis axis) const { return m_tracks.value(axis).position; }
    qint64 now() const { return m_clock.elapsed(); }
    int referenceDeadlineMs() const { return m_referenceDeadlineMs; }
    void setReferenceDeadline(int ms) { m_referenceDeadlineMs = ms; }

private:
    bool completeMotion(Axis axis); // the bookkeeping of an arrival; true for a jog chunk
    void checkDeadlines();
    void armDeadlineTimer();
    void markLost(Axis axis);
    void markOverdue(Axis axis);
    void updateMotionUnconfirmed();

    EmisHost& m_host;
    EmisKnownValues& m_known;
    Hooks m_hooks;
    QMap<Axis, Track> m_tracks;
    QTimer m_deadlineTimer; // parented to the adapter: moves to its thread with it
    QElapsedTimer m_clock;
    int m_referenceDeadlineMs = 120000;
};

} // namespace stepdeck::emis
