// Calibration and closed-loop reference runs of a simulated drive; the readings of manual 8.1
// are listed in NanotecDriveClosedLoop.h.
#include "NanotecDriveClosedLoop.h"
#include <QtMath>

namespace stepdeck::nanotec {

namespace {
constexpr double kReferenceSearchRevolutions = 1.5; // beyond it no index mark will come
}

void DriveClosedLoop::setEncoderConnected(bool connected, qint64 lastReading)
{
    if (m_encoder && !connected)
        m_frozenEncoder = lastReading;
    m_encoder = connected;
}

void DriveClosedLoop::begin(Run run, qint64 stepsPerRevolution, double physical, int direction,
                            double referenceSpeed)
{
    m_run = run;
    m_revolution = double(qMax<qint64>(1, stepsPerRevolution));
    m_elapsedMs = 0;
    m_travelled = 0;
    m_direction = direction >= 0 ? 1 : -1;
    if (run == Run::Calibration) {
        m_calibrated = false; // the old calibration is replaced by this run's
        m_speed = 2.0 * m_revolution / (m_calibrationMs / 1000.0);
        return;
    }
    m_referenced = false;
    m_speed = qMax(1.0, referenceSpeed);
    // The next index mark (a multiple of one revolution) strictly ahead of the rotor.
    const double ahead = physical + 0.5 * m_direction;
    const double mark = m_direction > 0 ? (qFloor(ahead / m_revolution) + 1) * m_revolution
                                        : (qCeil(ahead / m_revolution) - 1) * m_revolution;
    m_distance = qAbs(mark - physical);
}

DriveClosedLoop::Motion DriveClosedLoop::advance(double dt)
{
    switch (m_run) {
    case Run::None:
        return {};
    case Run::Calibration:
        return calibrationStep(dt);
    case Run::Reference:
        return referenceStep(dt);
    }
    return {};
}

DriveClosedLoop::Motion DriveClosedLoop::calibrationStep(double dt)
{
    // One revolution forward in the first half of the time, back in the second.
    const double half = m_calibrationMs / 2.0;
    auto offset = [this, half](double ms) {
        const double t = qBound(0.0, ms, double(m_calibrationMs));
        return t <= half ? m_revolution * t / half : m_revolution * (2.0 - t / half);
    };
    const double before = m_elapsedMs;
    m_elapsedMs += dt * 1000.0;
    Motion m;
    if (!m_encoder && m_elapsedMs >= half) {
        m.steps = offset(half) - offset(before);
        m.finished = m.failed = true; // no encoder counts for a whole revolution
    } else {
        m.steps = offset(m_elapsedMs) - offset(before);
        m.finished = m_elapsedMs >= m_calibrationMs;
    }
    m.speed = m.finished ? 0 : m_speed;
    if (m.finished) {
        m_run = Run::None;
        m_calibrated = !m.failed;
    }
    return m;
}

DriveClosedLoop::Motion DriveClosedLoop::referenceStep(double dt)
{
    const double limit = m_encoder ? m_distance : kReferenceSearchRevolutions * m_revolution;
    const double step = qMin(m_speed * dt, limit - m_travelled);
    m_travelled += step;
    Motion m;
    m.steps = step * m_direction;
    m.finished = m_travelled >= limit;
    m.failed = m.finished && !m_encoder;
    m.speed = m.finished ? 0 : m_speed;
    if (m.finished) {
        m_run = Run::None;
        m_referenced = !m.failed;
    }
    return m;
}

void DriveClosedLoop::interrupt()
{
    if (m_run == Run::Calibration)
        m_calibrated = false;
    if (m_run == Run::Reference)
        m_referenced = false;
    m_run = Run::None;
}

} // namespace stepdeck::nanotec
