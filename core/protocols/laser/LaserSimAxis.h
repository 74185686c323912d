#pragma once
#include <QtGlobal>

namespace stepdeck::laser {

// The mechanics of one simulated motor axis behind the laser protocol.
struct LaserSimAxisConfig
{
    double speed = 10000; // laser units per second, no ramps
    // Physical position of the end switch, "at the opposite side of the homeswitch". The
    // default lies beyond the protocol's range: a target never reaches it.
    qint64 endSwitch = 100000;
};

// One motor axis as the manual describes it: positions count from the home switch, which is
// "also the '0' position of the axis"; an axis that has not been home since power-up homes
// first and then proceeds to the target; a new target replaces the old one; the end switch
// stops the motor. Positions advance by the time slices the simulator feeds. Pure (no Qt
// objects, no timers).
class LaserSimAxis
{
public:
    enum class Event { None, HomeReached, TargetReached, EndSwitch };

    LaserSimAxisConfig& config() { return m_config; }
    const LaserSimAxisConfig& config() const { return m_config; }

    // Power-up: the carriage stands `physical` units from the home switch; its own count
    // starts at 0 there and becomes the real position only once it has been home.
    void powerOn(qint64 physical);

    void home();               // command '1'
    void moveTo(int target);   // command '2'
    void setHalted(bool halt); // door open: stands still, keeps its target
    void stop();               // emergency stop: stands still, forgets its target
    Event advance(double seconds);

    qint64 position() const; // the axis' own count, as reported in status frames
    double physical() const { return m_physical; }
    bool homed() const { return m_homed; }
    bool halted() const { return m_halted; }
    bool hasTarget() const { return m_phase != Phase::Idle; }
    bool isMoving() const { return hasTarget() && !m_halted; }
    int target() const { return m_target; }
    bool endSwitchActive() const { return m_physical >= double(m_config.endSwitch); }
    bool homeSwitchActive() const { return m_physical <= 0.0; }

private:
    enum class Phase { Idle, Homing, Moving };
    Event advanceHoming(double distance);
    Event advanceMoving(double distance);

    LaserSimAxisConfig m_config;
    Phase m_phase = Phase::Idle;
    bool m_thenMove = false; // homing on the way to a target
    int m_target = 0;
    double m_physical = 0;
    double m_offset = 0; // physical position where the axis' own count is 0
    bool m_homed = false;
    bool m_halted = false;
};

} // namespace stepdeck::laser
