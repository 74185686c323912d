#pragma once
#include "model/Axis.h"
#include <QList>
#include <QMap>

namespace stepdeck::nanotec {

// Which drives a status sweep reads, and what of each (issue 32, step 4). Pure: no I/O, no
// clock; NanotecStatus asks it before every sweep.
//
// A bus carries up to 254 drives (1.1) at 19200 baud, and one '$' exchange alone takes about
// 6 ms: reading every drive in every sweep would read a moving drive every 3 s. So a sweep is
// bounded by a budget of wire time (kSweepBudgetMs, within the 50 ms poll interval):
// - every active drive (a positioning or reference run pending, a jog, a velocity move) is in
//   every sweep, moving drives first: a moving drive is read once per sweep, and its arrival
//   is seen in the sweep after it;
// - the idle drives share what the budget leaves, oldest first (round robin), at least one per
//   sweep, so none starves however many drives move; while a positioning run is pending (lean
//   sweeps) on a bus of up to kLeanSkipMaxIdle idle drives only every fourth sweep, so that
//   the run's arrival is seen sooner (issue 30);
// - an idle drive's visit is its status '$'; its position 'C' and its inputs 'ZY' come every
//   eighth visit (staggered, and the drives' turns staggered too, so every sweep costs about
//   the same), and 'C' always when its status changed or a run just ended
//   (NanotecStatus::pollDrive decides the latter, it sees the reply). Standing still, an idle
//   drive's position changes only with its status; its inputs are read for display;
// - a silent drive costs a whole reply timeout: one of them is asked every tenth sweep.
// A bus whose drives all fit the budget keeps today's sweep: every drive, every time.
class NanotecPollPlan
{
public:
    // The sweep's wire time: within the 50 ms poll interval (ControllerOptions::pollIntervalMs
    // default), less a margin for the estimate.
    static constexpr double kSweepBudgetMs = 48;
    static constexpr int kIdleDetailEveryVisits = 8;
    static constexpr int kLeanSkipMaxIdle = 32;
    static constexpr int kSilentEverySweeps = 10;

    struct Drive
    {
        Axis axis;
        bool active = false; // pending run, jog or velocity move
        bool responding = true;
    };
    struct Read
    {
        Axis axis;
        bool active = false;
        bool positionWhileRunning = true; // 'C' even while its run is still pending
        bool position = true;             // 'C' of a drive at rest
        bool inputs = false;              // 'ZY'
    };

    // characterUs: the line's time per character (19200 8N1: 520.8 us).
    explicit NanotecPollPlan(double characterUs) : m_characterUs(characterUs) {}

    // The next sweep. lean: a run is pending and the poller is expedited; the running drives'
    // positions are then read every other sweep (their '$' every sweep).
    QList<Read> next(const QList<Drive>& drives, bool lean);

    // Estimated wire time of one exchange, in ms (request, reply, a turnaround allowance).
    double statusMs() const;   // '$'
    double positionMs() const; // 'C'
    double inputsMs() const;   // 'ZY'
    quint64 sweeps() const { return m_sweeps; }

private:
    double costOf(const Read& r) const;
    // The responding active drives, in axis order: in every sweep, first.
    QList<Read> activeReads(const QList<Drive>& drives, bool lean) const;
    // Idle drives in round-robin order after the last one visited.
    QList<Axis> idleInTurn(const QList<Drive>& drives) const;
    Read idleRead(Axis axis);

    double m_characterUs;
    quint64 m_sweeps = 0;
    std::optional<Axis> m_lastIdle;
    std::optional<Axis> m_lastSilent;
    QMap<Axis, quint64> m_visits; // idle visits per drive
};

} // namespace stepdeck::nanotec
