#pragma once
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/ParameterSchema.h"
#include <utility>
#include <vector>

namespace stepdeck::motion {

// One axis' speed of a feed move as programmed, in the axis' unit per second.
struct AxisSpeed
{
    int axis = -1;        // machine axis index
    double perSecond = 0; // F on the axis, its share of F, or G93's rate
    // A resolved rate (G93, the shares of F on a coordinating controller): the rates of a
    // controller go together, so one factor slows them all (as LinuxCNC slows the whole move).
    bool together = false;
};

// A move of its own (not in a step stream): what the move executor (MoveExecutor) runs and
// the check judges (issue 49 item 3). A feed move (G1, an arc's chord, a drilling cycle's feed)
// writes each controller's feed-rate parameter first; a positioning move (G0, a cycle's rapid)
// runs at the fast speed, put back first where a feed move changed it.
struct RatedMove
{
    int line = 0;
    bool feed = false;
    // Machine axis index and its machine position (absolute) or distance (relative).
    std::vector<std::pair<int, double>> targets;
    bool absolute = true;
    // The axes that get a rate (feed moves); empty: none is written (an arc's later chords run
    // at the rate its first wrote).
    std::vector<AxisSpeed> speeds;
    bool inverseTime = false; // G93: resolved rates are not held within the parameter's range
};

// The rates a move of its own writes (docs/programs.md "How F maps onto each model", "Limits",
// issue 50): the one place the check (its errors, notes, estimate) and the run (the writes it
// sends) take a feed move's per-axis rates from. Pure.
namespace MoveRates {

// An axis' speed in steps/s, rounded, at least 1 (beyond 9e15: 9e15, out of every range).
qint64 stepsPerSecond(const machine::MachineAxis& axis, double unitsPerSecond);

// The highest rate a controller runs one axis of a feed move at.
struct Ceiling
{
    qint64 rate = 0; // steps/s; 0: none known (no feed-rate parameter spec, nothing held)
    // Bound by the parameter the feed rate must stay below (Capabilities::contourTickBelow),
    // not by the feed-rate parameter's own range.
    bool belowParameter = false;
};
// The feed-rate parameter's schema maximum, and where the model's feed mode has no ramp
// (Capabilities::feedRateUsesFeedMode with contourTickBelow: the E-LAB's feed speed below its
// start speed, manual "SetFeedSpeed") one below the value the device holds there (known).
Ceiling highestRate(const Capabilities& caps, const ParameterSpec* rateSpec,
                    const ParameterSet& known, Axis axis);

// One axis' rate of a feed move, in steps/s: as programmed and as the controller is written.
struct AxisRate
{
    qint64 programmed = 0; // F (G94), its share of F or G93's rate; 0: the axis gets none
    qint64 runs = 0;       // what the controller is written (0: none)
    // The share of the programmed feed the axis runs at: runs / programmed for an axis at F;
    // where the move's rates go together (G93, coordinated shares) the one factor that slows
    // every axis of its controller, so that they still arrive together.
    double feedFactor = 1.0;
    bool limited = false; // this axis' own rate was above its ceiling, and the policy clamps
    Ceiling ceiling;
};
// The rate of machine axis `axisIndex` for `move` on its controller (caps, rateSpec: the
// controller's feed-rate parameter spec, null when not known; known: what the device holds).
// An axis at F runs at most at its ceiling (LimitPolicy::Clamp); rates that go together are
// slowed by the same factor. A share (G94) then stays within the parameter's range: below its
// minimum it runs at it (it arrives a little early), above its maximum (a feed override) at it.
AxisRate axisRate(const machine::MachineDescription& d, int axisIndex, const Capabilities& caps,
                  const ParameterSpec* rateSpec, const ParameterSet& known, const RatedMove& move);

// The feed-rate write of a feed move on one controller: the model's feed-rate parameter with
// each of the move's axes on that controller at axisRate's rate. Where the model writes every
// axis at once (Capabilities::feedRateWholeSet, E-LAB <FS>) its axes that do not move get a
// value too: the one the device is known to hold (known), else the move's slowest rate on that
// controller (a rate the moving axes are refused for first), so the write never depends on a
// value nobody wrote. Empty when the controller takes no rate or the move has no speeds.
ParameterSet feedRateWrite(const machine::MachineDescription& d, const QString& controller,
                           const Capabilities& caps, const RatedMove& move,
                           const ParameterSet& known, const ParameterSpec* rateSpec);

} // namespace MoveRates
} // namespace stepdeck::motion
