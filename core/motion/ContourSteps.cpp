#include "ContourSteps.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::motion {

namespace {
// A slot may move at most this share of a step per tick: 1 exactly would step once a tick
// too, but the path distance is summed tick by tick in floating point.
constexpr double kMostStepPerTick = 1.0 - 1e-9;
constexpr double kLowestFeedFactor = 0.1;
} // namespace

ContourSteps::ContourSteps(const StepScale& scale, const Position& origin,
                           const StepPosition& originSteps, double tickRate, double maxFeedFactor,
                           size_t queueCapacity)
    : m_scale(scale), m_origin(origin), m_originSteps(originSteps), m_tickRate(tickRate),
      m_maxFactor(std::max(maxFeedFactor, 1.0)), m_queue(queueCapacity), m_chainEnd(origin),
      m_steps(originSteps)
{}

double ContourSteps::neededTickRate(const CanonicalMove& move, const StepScale& scale,
                                    double feedFactor)
{
    double fastest = 0; // steps/s of the slot that steps most often
    for (int i = 0; i < move.axisCount && i < scale.axisCount; ++i)
        fastest = std::max(fastest, move.slotRatePerFeed(i) * move.feed * feedFactor *
                                        std::fabs(scale.stepsPerUnit[size_t(i)]));
    return fastest / kMostStepPerTick;
}

double ContourSteps::highestFeed(const CanonicalMove& move, const StepScale& scale, double tickRate)
{
    CanonicalMove atOne = move;
    atOne.feed = 1.0;
    const double perFeed = neededTickRate(atOne, scale);
    return perFeed > 0 ? tickRate / perFeed : 0;
}

QString ContourSteps::append(const CanonicalMove& move)
{
    if (m_closed)
        return tr("the contour is closed: no move follows its end");
    if (m_queue.isFull())
        return tr("the contour's queue is full (%1 moves)").arg(m_queue.capacity());
    if (move.kind == CanonicalMove::Kind::Rapid)
        return tr("a rapid is not part of a contour: the stream ends before it");
    if (const QString why = move.invalidReason(); !why.isEmpty())
        return why;
    if (move.axisCount != m_scale.axisCount)
        return tr("a move over %1 axes in a stream of %2")
            .arg(move.axisCount)
            .arg(m_scale.axisCount);
    for (int i = 0; i < move.axisCount; ++i) {
        const double spu = std::fabs(m_scale.stepsPerUnit[size_t(i)]); // < 0: inverted
        if (std::fabs(move.start[size_t(i)] - m_chainEnd[size_t(i)]) * spu > 0.5)
            return tr("line %1 does not start where the contour stands (axis %2: %3, not %4)")
                .arg(move.line)
                .arg(i + 1)
                .arg(move.start[size_t(i)])
                .arg(m_chainEnd[size_t(i)]);
    }
    const double needed = neededTickRate(move, m_scale);
    if (needed > m_tickRate)
        return tr("line %1: its feed needs %2 ticks/s, the stream runs %3 (highest feed %4 "
                  "unit/s)")
            .arg(move.line)
            .arg(std::ceil(needed))
            .arg(m_tickRate)
            .arg(highestFeed(move, m_scale, m_tickRate));
    m_chainEnd = move.end;
    ++m_movesTaken;
    if (move.length() > 0) {
        m_queue.push(move);
        // The override this move can run at: as far as one step per tick allows.
        m_caps.push_back(needed > 0 ? m_tickRate / needed : m_maxFactor);
    } else {
        m_lastLine = move.line;
        ++m_movesDone;
    }
    return {};
}

void ContourSteps::setStepLimits(int slot, const QString& name, qint64 minimum, qint64 maximum)
{
    if (slot < 0 || slot >= kMaxAxes)
        return;
    // Two sources (the machine's soft limits, the controller's own) both hold: the tighter.
    Limit& l = m_limits[size_t(slot)];
    if (l.set) {
        minimum = std::max(minimum, l.minimum);
        maximum = std::min(maximum, l.maximum);
    }
    l = Limit{true, name, minimum, maximum};
}

// False (the contour ends, fault() set) when `target` leaves a slot's soft limits.
bool ContourSteps::withinLimits(const StepPosition& target, int line)
{
    for (int i = 0; i < m_scale.axisCount; ++i) {
        const Limit& l = m_limits[size_t(i)];
        const qint64 t = target[size_t(i)];
        if (!l.set || (t >= l.minimum && t <= l.maximum))
            continue;
        m_fault = tr("line %1 would take axis %2 to %3 steps, beyond its soft limit %4: the "
                     "contour ends before it")
                      .arg(line)
                      .arg(l.name)
                      .arg(t)
                      .arg(t > l.maximum ? l.maximum : l.minimum);
        m_queue.clear();
        m_caps.clear();
        m_closed = true;
        return false;
    }
    return true;
}

void ContourSteps::setFeedFactor(double factor)
{
    m_factor = std::clamp(factor, kLowestFeedFactor, m_maxFactor);
}

// Rounded as a whole, not as a distance from the origin: where the origin is the step nearest
// to it (as after any move to a target), every position is the step nearest to the ideal path,
// the one a positioning move to the same point would reach.
StepPosition ContourSteps::stepsAt(const CanonicalMove& move, double s) const
{
    const Position p = move.at(s);
    StepPosition out = m_originSteps;
    for (int i = 0; i < m_scale.axisCount; ++i) {
        const double spu = m_scale.stepsPerUnit[size_t(i)];
        out[size_t(i)] +=
            std::llround(p[size_t(i)] * spu) - std::llround(m_origin[size_t(i)] * spu);
    }
    return out;
}

double ContourSteps::queuedSeconds() const
{
    double seconds = 0;
    for (size_t i = 0; i < m_queue.size(); ++i) {
        const CanonicalMove& move = m_queue.at(i);
        const double left = i == 0 ? move.length() - m_s : move.length();
        seconds += std::max(0.0, left) / speed(i);
    }
    return seconds;
}

double ContourSteps::speed(size_t i) const
{
    return m_queue.at(i).feed * std::min(m_factor, m_caps.at(i));
}

void ContourSteps::popFront()
{
    ++m_movesDone;
    m_lastLine = m_queue.front().line;
    m_queue.pop();
    m_caps.pop_front();
    m_frontLength = -1;
}

int ContourSteps::pull(StepTick* out, int max)
{
    int n = 0;
    while (n < max && !m_queue.isEmpty()) {
        const CanonicalMove* move = &m_queue.front();
        if (m_frontLength < 0)
            m_frontLength = move->length();
        // Where the path stands at the next tick: past the front move's end the rest of the
        // tick's time goes on along the next move, at its own feed.
        double s = m_s + speed(0) / m_tickRate;
        double length = m_frontLength;
        size_t index = 0;
        bool last = false;
        while (s >= length) {
            if (index + 1 < m_queue.size()) {
                const double restSeconds = (s - length) / speed(index);
                move = &m_queue.at(++index);
                s = restSeconds * speed(index);
                length = move->length();
            } else if (m_closed) {
                s = length; // the stream's last tick ends at its end point
                last = true;
                break;
            } else {
                return n; // the next move is not known yet
            }
        }
        for (size_t k = 0; k < index; ++k)
            popFront();
        m_frontLength = length;
        const StepPosition target = stepsAt(*move, s);
        if (!withinLimits(target, move->line))
            return n;
        StepTick& tick = out[n++];
        for (int i = 0; i < m_scale.axisCount; ++i) {
            const qint64 d = target[size_t(i)] - m_steps[size_t(i)];
            // append() bounds every slot's rate by the tick: d is -1, 0 or 1 (counted if not,
            // and never sent as more than one step).
            if (d < -1 || d > 1)
                ++m_clamped;
            tick.step[size_t(i)] = qint8(std::clamp<qint64>(d, -1, 1));
            m_steps[size_t(i)] += tick.step[size_t(i)];
        }
        for (int i = m_scale.axisCount; i < kMaxAxes; ++i)
            tick.step[size_t(i)] = 0;
        m_s = s;
        ++m_ticks;
        if (last) {
            popFront();
            m_s = 0;
        }
    }
    return n;
}

} // namespace stepdeck::motion
