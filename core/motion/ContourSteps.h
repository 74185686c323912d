#pragma once
#include "CanonicalMove.h"
#include "MotionQueue.h"
#include <QCoreApplication>
#include <array>
#include <deque>

namespace stepdeck::motion {

using StepPosition = std::array<qint64, kMaxAxes>;

// One tick of a step stream: per slot -1, 0 or +1 step. The E-LAB takes one such vector per
// tick of its feed rate, and a vector without step bits is a tick without a step (manual,
// "SetFeedStepXYZ": "Der Controller leert nämlich seinen XYZ Step Buffer mit der vorgegebenen
// Feedrate").
struct StepTick
{
    std::array<qint8, kMaxAxes> step{};
};

// How a stream's slots count: steps per unit of each slot's axis.
struct StepScale
{
    int axisCount = 0;
    std::array<double, kMaxAxes> stepsPerUnit{};
};

// A contour as a step stream laid on ticks (issue 30, "one <DC2> stream per contour"): the
// feed moves of a chain (lines and arcs, one after the other, nothing between them) are
// walked at their feed along the path, one tick every 1/tickRate s, and each tick's vector
// takes every slot to the step nearest the ideal path there. So:
// - the path speed is the programmed feed in every direction (the ticks come at a fixed rate,
//   whatever share of them carries a step on which axis), carried on across the joins of the
//   moves;
// - at every tick each slot is within half a step of the ideal path (lines and arcs are
//   computed in steps, no chords);
// - no slot steps more than once a tick: append() refuses a move whose feed needs a faster
//   tick than the stream has (neededTickRate()).
// A pull source: the executor takes ticks as the wire has room, appends moves as the program
// gives them (a bounded queue) and closes the chain before a rapid, a dwell, an M word, a
// pause or the end. Pure: no I/O, no timers.
class ContourSteps
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::motion::ContourSteps)
public:
    // origin: where the slots stand in units, originSteps the same in steps (a position p
    // becomes originSteps + round(p * stepsPerUnit) - round(origin * stepsPerUnit)); a slot's
    // stepsPerUnit < 0 counts the other way (an inverted axis). maxFeedFactor: the largest feed
    // override the stream may be set to.
    ContourSteps(const StepScale& scale, const Position& origin, const StepPosition& originSteps,
                 double tickRate, double maxFeedFactor = 1.0, size_t queueCapacity = 64);

    // The tick rate a move needs at feedFactor so that no slot steps more than once a tick.
    static double neededTickRate(const CanonicalMove& move, const StepScale& scale,
                                 double feedFactor = 1.0);
    // The highest feed (unit/s) `move`'s path can have at tickRate.
    static double highestFeed(const CanonicalMove& move, const StepScale& scale, double tickRate);

    // Queues a feed move of the chain: empty, or why not (the queue is full, a rapid, not where
    // the chain stands, a feed too fast for the tick). A move of length 0 is taken and adds
    // nothing.
    QString append(const CanonicalMove& move);
    bool canAppend() const { return !m_queue.isFull() && !m_closed; }
    // No move follows: the stream ends at the last move's end.
    void close() { m_closed = true; }
    bool isClosed() const { return m_closed; }
    // Up to max ticks into out. Fewer when the queued moves end within the next tick and the
    // chain is not closed (the caller appends and pulls again: an underrun if it cannot); 0
    // once finished().
    int pull(StepTick* out, int max);
    bool finished() const { return m_closed && m_queue.isEmpty(); }

    // A slot's soft limits in the stream's steps (as originSteps): the first tick that would
    // leave them is not given; the contour ends there (finished()) and fault() says why.
    // Called again for a slot, the limits narrow to what both allow.
    void setStepLimits(int slot, const QString& name, qint64 minimum, qint64 maximum);
    QString fault() const { return m_fault; }

    // The feed override for the ticks not given yet, clamped to 0.1..maxFeedFactor. A move
    // whose feed at the override would need more than one step per tick runs at the most its
    // tick allows (as LinuxCNC clamps an override at the axes' limits); append() judges a
    // move at 100 %.
    void setFeedFactor(double factor);
    double feedFactor() const { return m_factor; }
    double tickRate() const { return m_tickRate; }

    const StepPosition& steps() const { return m_steps; } // after the ticks given
    qint64 ticks() const { return m_ticks; }
    // Steps a tick would have needed beyond one on a slot (0 unless the rate bound failed).
    qint64 clampedSteps() const { return m_clamped; }
    int currentLine() const { return m_queue.isEmpty() ? m_lastLine : m_queue.front().line; }
    // Moves append() took, and of them those whose last tick was given (a move of length 0
    // counts as done when taken): the run reports a block finished as its ticks pass.
    qint64 movesTaken() const { return m_movesTaken; }
    qint64 movesDone() const { return m_movesDone; }
    // The time the queued path takes beyond the ticks given, at the current feed override.
    double queuedSeconds() const;
    // Where the queued path ends (the next move must start there), in units.
    const Position& chainEnd() const { return m_chainEnd; }
    // The steps each slot must have when a move's path stands at s (tests and the simulator's
    // comparison use it too).
    StepPosition stepsAt(const CanonicalMove& move, double s) const;

private:
    void popFront();
    double speed(size_t i) const; // queued move i's path speed at the override, unit/s
    bool withinLimits(const StepPosition& target, int line);

    StepScale m_scale;
    Position m_origin;
    StepPosition m_originSteps;
    double m_tickRate;
    double m_maxFactor;
    double m_factor = 1.0;
    MotionQueue m_queue;
    std::deque<double> m_caps; // per queued move: the most override its tick allows
    Position m_chainEnd;
    bool m_closed = false;
    double m_s = 0;            // the path distance into the front move at the last tick
    double m_frontLength = -1; // of the front move (-1: not known yet)
    StepPosition m_steps;
    qint64 m_ticks = 0;
    qint64 m_clamped = 0;
    qint64 m_movesTaken = 0;
    qint64 m_movesDone = 0;
    int m_lastLine = 0;
    struct Limit
    {
        bool set = false;
        QString name;
        qint64 minimum = 0, maximum = 0;
    };
    std::array<Limit, kMaxAxes> m_limits;
    QString m_fault;
};

} // namespace stepdeck::motion
