// Time-based motion of a simulated Nanotec drive: positioning with the drive's ramp, speed
// mode, flag positioning, reference runs, limit switches per 'l' and 'e', records with
// repetitions and follow-up records, auto status, and the motion of the closed-loop runs.
#include "NanotecDrive.h"
#include <QtMath>
#include <cmath>

namespace stepdeck::nanotec {

namespace {
constexpr double kIndexFreeSteps = 10; // 6.6 p=3: "eine feste Anzahl von Schritten"
}

bool NanotecDrive::isActive() const
{
    return m_run != Run::Idle || m_holdMs > 0 || m_notifyWhenReady;
}

void NanotecDrive::setSwitches(double negative, double positive)
{
    m_negSwitch = negative;
    m_posSwitch = positive;
    m_wasSwitch = externalSwitchActuated();
}

bool NanotecDrive::externalSwitchActuated() const
{
    return m_physical <= m_negSwitch || m_physical >= m_posSwitch;
}

double NanotecDrive::acceleration() const
{
    // 6.11: acceleration in Hz/ms = 3000 / sqrt(b) - 11.7
    const double perMs = 3000.0 / qSqrt(double(qMax<qint64>(1, m_params.value('b')))) - 11.7;
    return qMax(0.01, perMs) * 1000.0;
}

qint64 NanotecDrive::stepsPerRevolution() const
{
    const qint64 fullSteps = m_params.value('a') == 9 ? 400 : 200;
    const qint64 g = m_params.value('g');
    return fullSteps * (g == 255 ? 1 : qMax<qint64>(1, g));
}

bool NanotecDrive::atIndexMark() const
{
    if (!m_closedLoop.encoderConnected())
        return false; // the index mark is the encoder's (5.30 bit 6)
    const double rev = double(stepsPerRevolution());
    return qAbs(m_physical - qRound64(m_physical / rev) * rev) < 0.5;
}

int NanotecDrive::switchBehaviour(bool external, bool reference) const
{
    // 5.6: reference groups bits 0-1 / 9-10, normal-run groups bits 2-5 / 11-14.
    const int first = external ? (reference ? 9 : 11) : (reference ? 0 : 2);
    const int count = reference ? 2 : 4;
    int found = -1;
    for (int b = first; b < first + count; ++b) {
        if (m_params.value('l') & (qint64(1) << b)) {
            if (found >= 0)
                return -1;
            found = b - first; // 0 free forward, 1 free backward, 2 stop, 3 ignore
        }
    }
    return found;
}

int NanotecDrive::freeDirection(int behaviour) const
{
    // "Freifahrt vorwaerts/rueckwaerts" (5.6), read relative to the run that reached the
    // switch: backwards backs off it (the factory setting 5154 does this for every group).
    return behaviour == 0 ? m_dir : -m_dir;
}

void NanotecDrive::moveBy(double steps)
{
    m_physical += steps;
    m_count += steps;
}

void NanotecDrive::start()
{
    if (!ready())
        return; // a run is in progress
    const qint64 mode = m_params.value('!');
    if (faults.closedLoopRunsIgnored && (mode == 8 || mode == 101))
        return;
    m_runsDone = 0;
    startRun();
}

void NanotecDrive::startRun()
{
    const qint64 mode = m_params.value('!');
    const qint64 p = m_params.value('p');
    m_reference = p == 3 || p == 4;
    m_internalRef = p == 3;
    m_flagTriggered = false;
    m_dir = m_params.value('d') ? 1 : -1;
    m_speed = double(m_params.value('u'));
    // Reading of an open point: 6.8 starts a run at 'u' and ramps up to 'o'; an 'o' below 'u'
    // (a coordinated chord's small share) is run at 'o' from the first step (stepPositioning
    // caps the speed at m_topSpeed). docs/programs.md says what a drive running it at 'u' would
    // do to the path.
    m_topSpeed = double(m_params.value('o'));
    m_lastPhysical = m_physical;
    m_wasSwitch = externalSwitchActuated();
    if (mode == 8 || mode == 101)
        return startClosedLoopRun(mode);
    if (m_reference && mode >= 1 && mode <= 4) {
        m_run = Run::RefSeek;
        if (m_internalRef)
            m_topSpeed = m_speed; // "mit der unteren Geschwindigkeit"
        else if (m_wasSwitch)
            beginFreeTravel(freeDirection(switchBehaviour(true, true)), true);
        return;
    }
    if (mode == 1 && p == 1) {
        m_target = m_count + m_dir * double(m_params.value('s'));
        m_run = Run::Position;
    } else if (mode == 1 && p == 2) {
        m_target = double(m_params.value('s'));
        m_dir = m_target >= m_count ? 1 : -1;
        m_run = Run::Position;
    } else if (mode == 2 && p == 1) {
        m_run = Run::Speed;
    } else if (mode == 3 && p == 1) {
        m_run = Run::Flag;
    }
    // Clock-direction, analog and joystick modes need signals the simulator has not got.
}

void NanotecDrive::beginFreeTravel(int dir, bool toReference)
{
    m_run = toReference ? Run::RefFree : Run::FreeTravel;
    m_dir = dir;
    m_speed = double(m_params.value('u')); // 5.6: "mit der eingestellten unteren Geschwindigkeit"
    m_freeLeft = m_internalRef && toReference ? kIndexFreeSteps : 0;
}

void NanotecDrive::stopNow()
{
    if (m_run == Run::Idle && m_holdMs <= 0)
        return;
    // 6.2: no ramp. Above the start frequency the rotor overshoots: the encoder sees steps
    // the counter never made.
    const double u = double(m_params.value('u'));
    if (m_run != Run::Idle && m_speed > u * 1.05)
        m_physical += m_dir * (qRound((m_speed - u) / 200.0) + 1);
    m_restartAfterHold = false;
    m_closedLoop.interrupt();
    finishRun(false);
    m_holdMs = 0; // 'S' brings the drive to ready at once
}

void NanotecDrive::finishRun(bool chain)
{
    const bool positioning = m_run == Run::Position || m_run == Run::Flag;
    m_run = Run::Idle;
    m_speed = 0;
    // The motor stands on a whole step, and the last fraction moves the encoder as well as the
    // counter: a speed-mode run stopped by 'S' (every jog's end) would otherwise leave them up
    // to half a step apart per run, until a position error after a few dozen jogs. The step is
    // completed in the run's direction, never taken back: a free travel ends just off its
    // switch, and rounding back would put the motor on the switch again.
    const double whole = m_dir > 0 ? std::ceil(m_count - 1e-6) : std::floor(m_count + 1e-6);
    moveBy(whole - m_count);
    // 5.9 / 5.13: after a run the encoder position is checked against the demand position.
    if (m_params.value('U') != 0 && !m_positionError &&
        qAbs(encoderPosition() - position()) > m_params.value('X')) {
        m_positionError = true;
        pushError(error::Position);
    }
    m_holdMs = double(m_params.value('O')) * 10.0; // 5.12 settle time
    m_notifyWhenReady = true;
    if (!chain || !positioning || m_reference || m_positionError)
        return;
    // 6.13-6.16: repetitions (W, 0 = endless), reversal (t), pause (P), next record (N).
    ++m_runsDone;
    const qint64 w = m_params.value('W');
    if (w == 0 || m_runsDone < w) {
        if (m_params.value('t'))
            m_params['d'] = m_params.value('d') ? 0 : 1;
        m_holdMs = qMax(m_holdMs, double(m_params.value('P')));
        m_restartAfterHold = true;
    } else if (const qint64 next = m_params.value('N'); next > 0) {
        loadRecord(int(next));
        m_runsDone = 0;
        m_holdMs = qMax(m_holdMs, double(m_params.value('P')));
        m_restartAfterHold = true;
    }
}

void NanotecDrive::stepPositioning(double dt)
{
    const double a = acceleration();
    const double u = double(m_params.value('u'));
    const double remaining = (m_target - m_count) * m_dir;
    if (remaining <= 0.5) {
        // The last fraction of a step moves the motor too, or the encoder drifts from the
        // counter run by run (a position error after some hundred short moves).
        moveBy(m_dir * remaining);
        m_count = m_target;
        return finishRun();
    }
    const double braking = (m_speed * m_speed - u * u) / (2 * a);
    if (remaining <= braking)
        m_speed = qMax(u, m_speed - a * dt);
    else
        m_speed = qMin(m_topSpeed, m_speed + a * dt);
    const double step = m_speed * dt;
    if (step >= remaining) {
        moveBy(m_dir * remaining);
        m_count = m_target;
        return finishRun();
    }
    moveBy(m_dir * step);
}

void NanotecDrive::stepSpeed(double dt)
{
    // 6.6 speed mode: speed ('o') and direction ('d') changes are ramped at once.
    const double a = acceleration();
    const double u = double(m_params.value('u'));
    const double target = (m_params.value('d') ? 1.0 : -1.0) * double(m_params.value('o'));
    double v = m_speed * m_dir;
    if ((v > 0) != (target > 0) && qAbs(v) <= u)
        v = target > 0 ? u : -u; // below the start frequency the drive reverses at once
    else if (v < target)
        v = qMin(target, v + a * dt);
    else
        v = qMax(target, v - a * dt);
    m_dir = v >= 0 ? 1 : -1;
    m_speed = qAbs(v);
    moveBy(v * dt);
}

void NanotecDrive::checkSwitches(QList<QByteArray>*)
{
    const bool now = externalSwitchActuated();
    const bool hit = now && !m_wasSwitch;
    m_wasSwitch = now;
    const double rev = double(stepsPerRevolution());
    const bool index = qFloor(m_lastPhysical / rev) != qFloor(m_physical / rev);
    m_lastPhysical = m_physical;
    if (m_run == Run::RefSeek) {
        if (!m_internalRef && now)
            beginFreeTravel(freeDirection(switchBehaviour(true, true)), true);
        else if (m_internalRef && index)
            beginFreeTravel(freeDirection(switchBehaviour(false, true)), true);
        return;
    }
    if (m_run != Run::Position && m_run != Run::Speed && m_run != Run::Flag)
        return;
    const int b = hit ? switchBehaviour(true, false) : index ? switchBehaviour(false, false) : 3;
    if (b == 0 || b == 1) {
        beginFreeTravel(freeDirection(b), false);
        m_freeLeft = hit ? 0 : kIndexFreeSteps; // an index mark is left after fixed steps
    } else if (b == 2) {
        finishRun(); // "Stopp": the switch stays pressed
    }
}

void NanotecDrive::stepFreeTravel(double dt)
{
    double step = m_speed * dt;
    if (m_freeLeft > 0)
        step = qMin(step, m_freeLeft);
    moveBy(m_dir * step);
    const bool done = m_freeLeft > 0 ? (m_freeLeft -= step) <= 0 : !externalSwitchActuated();
    if (done) {
        if (m_run == Run::RefFree) { // the reference position (6.6)
            m_count = 0;
            m_encoderOffset = m_physical;
        }
        m_freeLeft = 0;
        finishRun();
    }
}

QList<QByteArray> NanotecDrive::advance(double dt)
{
    QList<QByteArray> out;
    switch (m_run) {
    case Run::Idle:
        break;
    case Run::Position:
        stepPositioning(dt);
        break;
    case Run::Speed:
        stepSpeed(dt);
        break;
    case Run::ClosedLoop:
        stepClosedLoop(dt);
        break;
    case Run::Flag:
        if (m_flagTriggered) {
            stepPositioning(dt);
        } else {
            m_speed = qMin(m_topSpeed, m_speed + acceleration() * dt);
            moveBy(m_dir * m_speed * dt);
        }
        break;
    case Run::RefSeek:
        m_speed = qMin(m_topSpeed, m_speed + acceleration() * dt);
        moveBy(m_dir * m_speed * dt);
        break;
    case Run::RefFree:
    case Run::FreeTravel:
        stepFreeTravel(dt);
        break;
    }
    if (m_run != Run::Idle)
        checkSwitches(&out);
    if (m_run == Run::Idle && m_holdMs > 0) {
        m_holdMs -= dt * 1000.0;
        if (m_holdMs <= 0) {
            m_holdMs = 0;
            if (m_restartAfterHold) {
                m_restartAfterHold = false;
                m_notifyWhenReady = false;
                startRun();
            }
        }
    }
    if (m_notifyWhenReady && ready()) {
        m_notifyWhenReady = false;
        if (m_params.value('J') == 1) // 5.31: 'j' instead of '$'
            out << "j" + QByteArray::number(statusWord());
    }
    return out;
}

// ---------------------------------------------------------------- closed-loop runs (8.1)
// The run itself is DriveClosedLoop's (NanotecDriveClosedLoop.h); the drive moves by it.

void NanotecDrive::startClosedLoopRun(qint64 mode)
{
    const bool calibration = mode == 101;
    if (calibration)
        m_long["CL_enable"] = 0; // our reading: the motor is calibrated in open loop
    m_closedLoop.begin(calibration ? DriveClosedLoop::Run::Calibration
                                   : DriveClosedLoop::Run::Reference,
                       stepsPerRevolution(), m_physical, m_dir, double(m_params.value('u')));
    m_reference = false;
    m_run = Run::ClosedLoop;
}

void NanotecDrive::stepClosedLoop(double dt)
{
    const bool reference = m_closedLoop.running() == DriveClosedLoop::Run::Reference;
    const DriveClosedLoop::Motion m = m_closedLoop.advance(dt);
    moveBy(m.steps);
    m_speed = m.speed;
    if (m.steps != 0)
        m_dir = m.steps > 0 ? 1 : -1;
    if (!m.finished)
        return;
    if (m.failed && !m_positionError) {
        m_positionError = true; // 5.21 bit 2, and ERROR_QEI in the error memory (5.15)
        pushError(error::Position);
    } else if (reference) {
        m_count = 0; // the index mark is the reference position (5.17)
        m_encoderOffset = m_physical;
    }
    finishRun(false);
}

} // namespace stepdeck::nanotec
