#include "ElabSimAxis.h"
#include <QtMath>

namespace stepdeck::elab {

namespace {
// Longest time slice integrated in one go: keeps the ramp (explicit Euler) accurate even when
// the event loop stalled and a long interval has to be caught up.
constexpr double kMaxSlice = 0.002;
} // namespace

// ------------------------------------------------------------------ switches

bool ElabSimAxis::limitActuated() const
{
    return m_limitForced || m_position <= m_switches.limitMin || m_position >= m_switches.limitMax;
}

bool ElabSimAxis::referenceActuated() const
{
    return m_referenceForced ||
           qAbs(m_position - m_switches.referencePosition) <= m_switches.referenceWindow;
}

bool ElabSimAxis::limitLevelHigh() const
{
    return limitActuated() == m_switches.limitWiredActiveHigh;
}

bool ElabSimAxis::referenceLevelHigh() const
{
    return referenceActuated() == m_switches.referenceWiredActiveHigh;
}

// SetSwitchPolarity: $FF = "1-schaltend bzw. high-active", $00 = "Null-schaltend bzw.
// low-active". The firmware sees a switch as active when the level equals that polarity.
bool ElabSimAxis::limitActive() const
{
    return limitLevelHigh() == m_limitPolarityHigh;
}
bool ElabSimAxis::referenceActive() const
{
    return referenceLevelHigh() == m_referencePolarityHigh;
}

// ------------------------------------------------------------------ commands

void ElabSimAxis::startFastMove(qint64 steps)
{
    m_stepsLeft = qAbs(steps);
    if (steps == 0) {
        finish();
        return;
    }
    m_direction = steps < 0 ? -1 : 1;
    m_mode = Mode::FastMove;
    m_speed = startSpeed();
    m_fraction = 0;
    m_stopping = false;
}

void ElabSimAxis::startFeed(qint64 steps)
{
    startFastMove(steps);
    if (steps != 0) {
        m_mode = Mode::Feed;
        m_speed = qMax<double>(1.0, m_ramp.feedSpeed);
    }
}

void ElabSimAxis::startReference(int direction)
{
    m_stepsLeft = 0;
    if (direction == 0)
        return;
    m_direction = direction < 0 ? -1 : 1;
    m_mode = Mode::Reference;
    m_speed = startSpeed();
    m_fraction = 0;
    m_stopping = false;
    // A switch that is active already ends the search at once ("bis ... der Referenz Schalter
    // aktiviert wird"): the axis does not move.
    if (referenceActive())
        finish();
}

void ElabSimAxis::setVelocity(int rate)
{
    // "Velocity Werte kleiner als die eingestellte StartStopFrequenz werden als 0 interpretiert
    // und führen zum Stop der Achse mit Bremsrampe."
    const double magnitude = qAbs(rate) < startSpeed() ? 0.0 : double(qAbs(rate));
    if (m_mode == Mode::Velocity) {
        m_targetSpeed = magnitude;
        m_stopping = magnitude == 0;
        return;
    }
    if (magnitude == 0)
        return;
    m_stepsLeft = 0;
    m_direction = rate < 0 ? -1 : 1;
    m_mode = Mode::Velocity;
    m_speed = startSpeed();
    m_targetSpeed = magnitude;
    m_fraction = 0;
    m_stopping = false;
}

void ElabSimAxis::setJogRate(int rate)
{
    // Jog: the rate takes effect at once, the host does the ramping ("Befehle im Jogbetrieb").
    if (rate == 0) {
        if (m_mode == Mode::Jog)
            finish();
        return;
    }
    if (m_mode != Mode::Jog) {
        m_stepsLeft = 0;
        m_fraction = 0;
    }
    m_mode = Mode::Jog;
    m_direction = rate < 0 ? -1 : 1;
    m_speed = m_targetSpeed = qAbs(rate);
    m_stopping = false;
}

void ElabSimAxis::rampStop()
{
    switch (m_mode) {
    case Mode::Idle:
        return;
    case Mode::Feed:
        // Feed runs below the start/stop rate ("kann jederzeit sofort gestartet und gestoppt
        // werden, ohne dass Schrittverluste auftreten"): no ramp needed. The remaining steps stay.
        m_mode = Mode::Idle;
        m_speed = 0;
        return;
    default:
        m_stopping = true;
        return;
    }
}

void ElabSimAxis::hardStop()
{
    if (m_mode == Mode::Idle)
        return;
    m_mode = Mode::Idle; // the unexecuted steps stay in m_stepsLeft
    m_speed = 0;
    m_stopping = false;
}

bool ElabSimAxis::singleStep(int direction)
{
    if (direction == 0)
        return true;
    m_position += direction < 0 ? -1 : 1;
    ++m_singleSteps;
    return !limitActive();
}

void ElabSimAxis::clearRemaining()
{
    if (m_mode == Mode::Idle)
        m_stepsLeft = 0;
}

void ElabSimAxis::reset()
{
    // The machine stays the same machine: switch positions, wiring, switches held by hand.
    const ElabSimSwitchConfig switches = m_switches;
    const bool limitForced = m_limitForced;
    const bool referenceForced = m_referenceForced;
    *this = ElabSimAxis();
    m_switches = switches;
    m_limitForced = limitForced;
    m_referenceForced = referenceForced;
}

// ------------------------------------------------------------------ motion

ElabSimAxis::Event ElabSimAxis::advance(double seconds)
{
    while (seconds > 0 && m_mode != Mode::Idle) {
        const double slice = qMin(seconds, kMaxSlice);
        seconds -= slice;
        const Event event = advanceSlice(slice);
        if (event != Event::None)
            return event;
    }
    return Event::None;
}

ElabSimAxis::Event ElabSimAxis::advanceSlice(double seconds)
{
    switch (m_mode) {
    case Mode::Idle:
        return Event::None;
    case Mode::Feed:
        m_speed = qMax<double>(1.0, m_ramp.feedSpeed); // follows <FS> changes
        break;
    case Mode::Jog:
        if (!m_stopping)
            break;
        [[fallthrough]];
    default:
        updateRampSpeed(seconds);
        if (m_mode == Mode::Idle)
            return Event::Finished; // braked down to the start rate: stopped
        break;
    }

    m_fraction += m_speed * seconds;
    qint64 steps = qint64(m_fraction);
    m_fraction -= double(steps);
    const bool counted = m_mode == Mode::FastMove || m_mode == Mode::Feed;
    if (counted)
        steps = qMin(steps, m_stepsLeft);
    for (qint64 i = 0; i < steps; ++i) {
        m_position += m_direction;
        if (counted)
            --m_stepsLeft;
        // "Wenn eine Fahrt einen Endschalter erreicht hat, dann wird diese auch immer sofort
        // abgebrochen, ausgenommen wiederum die Jog Bewegungen."
        if (m_mode != Mode::Jog && limitActive()) {
            hardStop();
            return Event::LimitHit;
        }
        // ReferenceMove: "bis ... der Referenz Schalter aktiviert wird. Dadurch wird ein
        // Schnellstop eingeleitet."
        if (m_mode == Mode::Reference && referenceActive()) {
            hardStop();
            return Event::ReferenceHit;
        }
    }
    if (counted && m_stepsLeft == 0) {
        finish();
        return Event::Finished;
    }
    return Event::None;
}

double ElabSimAxis::brakingDistance() const
{
    if (m_ramp.acceleration == 0)
        return 0;
    const double vs = startSpeed();
    return qMax(0.0, (m_speed * m_speed - vs * vs) / (2.0 * m_ramp.acceleration));
}

// Trapezoid: start at the start rate, accelerate towards the plateau, brake down to the start
// rate in time for the target (FastMove) or on a stop; at the start rate the axis stops. An
// acceleration of 0 means no ramp at all: the axis runs at the start rate.
void ElabSimAxis::updateRampSpeed(double seconds)
{
    const double vs = startSpeed();
    const double dv = double(m_ramp.acceleration) * seconds;
    double target = 0;
    switch (m_mode) {
    case Mode::FastMove:
    case Mode::Reference:
        target = qMax(vs, double(m_ramp.maxSpeed));
        break;
    default: // velocity; a stopping jog brakes with the same ramp
        target = m_targetSpeed;
        break;
    }
    if (m_mode == Mode::FastMove && !m_stopping &&
        double(m_stepsLeft) - m_fraction <= brakingDistance() + 1.0)
        target = vs;
    if (m_stopping || target == 0) {
        m_speed -= dv;
        if (m_speed <= vs || m_ramp.acceleration == 0)
            finish();
        return;
    }
    if (m_speed < target)
        m_speed = m_ramp.acceleration == 0 ? m_speed : qMin(target, m_speed + dv);
    else if (m_speed > target)
        m_speed = m_ramp.acceleration == 0 ? target : qMax(target, m_speed - dv);
}

void ElabSimAxis::finish()
{
    m_mode = Mode::Idle;
    m_speed = 0;
    m_targetSpeed = 0;
    m_fraction = 0;
    m_stopping = false;
}

} // namespace stepdeck::elab
