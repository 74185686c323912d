// Which drives a Nanotec status sweep reads (NanotecPollPlan.h).
#include "NanotecPollPlan.h"

namespace stepdeck::nanotec {

namespace {
// Characters per exchange with a three-digit address (1.1, 5.21, 5.17, 5.30):
// "#123$\r" + "123$17\r", "#123C\r" + "123C-1234567\r", "#123ZY\r" + "123ZY196671\r".
constexpr int kStatusChars = 13;
constexpr int kPositionChars = 19;
constexpr int kInputsChars = 19;
// The drive's and the host's turnaround per exchange (a reading: the manual gives none).
constexpr double kTurnaroundMs = 1.0;

std::optional<Axis> nextSilent(const QList<NanotecPollPlan::Drive>& drives,
                               std::optional<Axis> last)
{
    std::optional<Axis> first;
    for (const NanotecPollPlan::Drive& d : drives) {
        if (d.responding)
            continue;
        if (!first)
            first = d.axis;
        if (!last || d.axis > *last)
            return d.axis;
    }
    return first;
}
} // namespace

double NanotecPollPlan::statusMs() const
{
    return kStatusChars * m_characterUs / 1000.0 + kTurnaroundMs;
}

double NanotecPollPlan::positionMs() const
{
    return kPositionChars * m_characterUs / 1000.0 + kTurnaroundMs;
}

double NanotecPollPlan::inputsMs() const
{
    return kInputsChars * m_characterUs / 1000.0 + kTurnaroundMs;
}

double NanotecPollPlan::costOf(const Read& r) const
{
    const bool position = r.active ? r.positionWhileRunning : r.position;
    return statusMs() + (position ? positionMs() : 0.0) + (r.inputs ? inputsMs() : 0.0);
}

QList<Axis> NanotecPollPlan::idleInTurn(const QList<Drive>& drives) const
{
    QList<Axis> after, before;
    for (const Drive& d : drives) {
        if (d.active || !d.responding)
            continue;
        (!m_lastIdle || d.axis > *m_lastIdle ? after : before) << d.axis;
    }
    return after + before;
}

NanotecPollPlan::Read NanotecPollPlan::idleRead(Axis axis)
{
    // The first visit of each drive is staggered by its index: a bus that starts idle does
    // not read every position in its first round.
    const auto it = m_visits.find(axis);
    const quint64 visit =
        it != m_visits.end()
            ? (*it)++
            : *m_visits.insert(axis, quint64(axis.index() % kIdleDetailEveryVisits) + 1) - 1;
    Read r;
    r.axis = axis;
    r.position = visit % kIdleDetailEveryVisits == 0;
    r.inputs = visit % kIdleDetailEveryVisits == kIdleDetailEveryVisits / 2;
    return r;
}

QList<NanotecPollPlan::Read> NanotecPollPlan::next(const QList<Drive>& drives, bool lean)
{
    ++m_sweeps;
    bool anyResponding = false;
    for (const Drive& d : drives)
        anyResponding = anyResponding || d.responding;
    QList<Read> sweep = activeReads(drives, lean);
    double spent = 0;
    for (const Read& r : sweep)
        spent += costOf(r);
    // Nobody answers: walk every drive in turn (each sweep a miss until the link is lost).
    QList<Drive> candidates = drives;
    if (!anyResponding) {
        for (Drive& d : candidates)
            d.responding = true;
    }
    // While a run is pending (lean), three sweeps of four read only the running drives: the
    // next chord waits for the sweep that sees the last one arrive (issue 30). Not on a bus
    // of more idle drives than kLeanSkipMaxIdle: they would wait past 5 s for their turn.
    QList<Axis> idle = idleInTurn(candidates);
    if (lean && !sweep.isEmpty() && m_sweeps % 4 != 0 && idle.size() <= kLeanSkipMaxIdle)
        idle.clear();
    // Every drive fits: today's sweep (each idle drive read whole, inputs every fourth sweep).
    double allIdle = 0;
    for (int i = 0; i < idle.size(); ++i)
        allIdle += statusMs() + positionMs() + inputsMs() / 4;
    const bool everyDrive = !lean && spent + allIdle <= kSweepBudgetMs;
    bool tookIdle = false;
    for (Axis axis : idle) {
        Read r = idleRead(axis);
        if (everyDrive) {
            r.position = true;
            r.inputs = m_sweeps % 4 == 1;
        } else if (tookIdle && spent + costOf(r) > kSweepBudgetMs) {
            --m_visits[axis]; // not visited after all
            break;
        }
        tookIdle = true;
        spent += costOf(r);
        sweep << r;
        m_lastIdle = axis;
    }
    if (anyResponding && m_sweeps % kSilentEverySweeps == 0) {
        if (const std::optional<Axis> silent = nextSilent(drives, m_lastSilent)) {
            m_lastSilent = silent;
            Read r;
            r.axis = *silent;
            r.inputs = true;
            sweep << r;
        }
    }
    return sweep;
}

QList<NanotecPollPlan::Read> NanotecPollPlan::activeReads(const QList<Drive>& drives,
                                                          bool lean) const
{
    QList<Read> reads;
    for (const Drive& d : drives) {
        if (!d.active || !d.responding)
            continue;
        Read r;
        r.axis = d.axis;
        r.active = true;
        r.positionWhileRunning = !lean || m_sweeps % 2 == 0;
        r.inputs = m_sweeps % 4 == 1;
        reads << r;
    }
    return reads;
}

} // namespace stepdeck::nanotec
