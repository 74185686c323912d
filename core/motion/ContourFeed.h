#pragma once
#include "ContourSteps.h"
#include <QMutex>
#include <functional>

namespace stepdeck::motion {

// A contour shared between the thread that gives its moves (the program's executor, on the GUI
// thread) and the controller thread that sends its ticks (issue 30): ContourSteps behind a
// mutex. The consumer sets wakeUp(), which append() and close() call (on the giving thread)
// so that a stream waiting for its next move goes on without polling; wakeUp must only post to
// the consumer's thread.
class ContourFeed
{
public:
    explicit ContourFeed(ContourSteps steps) : m_steps(std::move(steps)) {}

    QString append(const CanonicalMove& move);
    void close();
    bool canAppend() const;
    bool finished() const;
    int pull(StepTick* out, int max);
    // Pulls that found no tick while the contour was still open (the consumer had to wait).
    qint64 starvedPulls() const;

    void setStepLimits(int slot, const QString& name, qint64 minimum, qint64 maximum);
    QString fault() const;
    // A feed hold (issue 30): no tick is given until it is released, so the stream runs dry
    // and the board stands where its last tick put it (the E-LAB's feed mode has no ramp: no
    // step is lost). Released, the stream goes on along the path from there.
    void setHeld(bool held);
    bool isHeld() const;
    void setFeedFactor(double factor);
    double tickRate() const; // fixed for the stream's life
    qint64 ticks() const;
    int currentLine() const;
    qint64 movesDone() const;     // ContourSteps::movesDone
    double queuedSeconds() const; // ContourSteps::queuedSeconds
    StepPosition steps() const;

    void setWakeUp(std::function<void()> wakeUp);

private:
    void wake();

    mutable QMutex m_mutex;
    ContourSteps m_steps;
    qint64 m_starved = 0;
    bool m_held = false;
    std::function<void()> m_wakeUp;
};

} // namespace stepdeck::motion
