#pragma once
#include "model/Axis.h"
#include <QByteArray>
#include <QString>
#include <optional>

namespace stepdeck::nanotec {

// The 'o' range (6.9): the highest step frequency a drive takes, for every part that sends one.
constexpr qint64 kMaxFrequency = 25000;

// "<cmd><value>" as the parts send it (the codec adds '#', the address and '\r').
inline QByteArray commandWithValue(const char* cmd, qint64 value)
{
    return QByteArray(cmd) + QByteArray::number(value);
}

enum class JogPhase { Idle, Starting, Running, Stopping };

// What the host knows of one drive on the bus (one per axis): its address, whether it
// answers, the last status, position and inputs read, the caches speed-mode ramps need, and
// the motion the host started on it.
struct HostDrive
{
    Axis axis = Axis::X;
    int address = 1;
    bool responding = true;
    int misses = 0;
    QString firmware;
    std::optional<qint64> status; // last '$' / 'j' word (5.21)
    qint64 position = 0;          // last 'C'
    std::optional<qint64> inputs; // last 'ZY' (5.30)
    qint64 limitSwitchType = 0;   // 'e' (5.7)
    qint64 minFrequency = 400;    // 'u', 'o', 'b' caches for speed-mode ramps
    qint64 maxFrequency = 1000;
    qint64 ramp = 2364;
    bool motionPending = false; // 'A' sent, waiting for ready
    bool referencing = false;
    bool positionErrorReported = false;
    JogPhase jog = JogPhase::Idle;
    bool jogBusy = false;       // a jog sequence is on the bus
    bool stopScheduled = false; // a zero rate waits out the ramp's zero crossing
    bool velocityMove = false;  // speed mode started by velocityMove (no lease)
    double jogDesired = 0;
    double jogApplied = 0;
    qint64 savedMaxFrequency = 0; // 'o' before speed mode, restored afterwards

    // Everything the host started on it is over (stop, panic, link loss).
    void forgetMotion()
    {
        jog = JogPhase::Idle;
        jogBusy = false;
        velocityMove = false;
        motionPending = false;
        referencing = false;
    }
};

} // namespace stepdeck::nanotec
