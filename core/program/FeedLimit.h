#pragma once
#include "ContourMoves.h"
#include "ProgramBlock.h"
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/ParameterSchema.h"
#include "motion/CanonicalMove.h"
#include <optional>

namespace stepdeck::program {

// Limits as LinuxCNC and GRBL apply them (issue 50, docs/programs.md "Limits"): a feed above
// the highest a move can run at runs at that highest (LinuxCNC limits a move's velocity to its
// axes' maximum velocities, GRBL to its $110..$112; neither refuses), and an S above the
// spindle's maxRpm runs at maxRpm (GRBL's $30). What a device cannot do more slowly (a rate
// below its lowest) is not limited here: the check refuses it. The one place the check (its
// note, its time estimate and preview) and the run (the rates it writes, the contour it streams)
// take the feed a move runs at from, so they cannot disagree. With the machine file's "limits":
// "refuse" (machine::LimitPolicy::Refuse) nothing is limited and the check refuses such feeds as
// it did before issue 50. Pure.
namespace FeedLimit {

// The highest rate a controller runs one axis of a G1 at.
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

// One axis' rate of a G1 (a block of its own, an arc's chords, a drilling cycle's feed), in
// steps/s: as the program asks for it and as the controller is written.
struct AxisRate
{
    qint64 programmed = 0; // F (G94), its share of F or G93's rate; 0: the axis gets none
    qint64 runs = 0;       // what the controller is written (0: none)
    // The share of the programmed feed the axis runs at: runs / programmed for an axis at F;
    // where the block's rates go together (G93, coordinated shares) the one factor that slows
    // every axis of its controller, so that they still arrive together.
    double feedFactor = 1.0;
    bool limited = false; // this axis' own rate was above its ceiling, and the policy clamps
    Ceiling ceiling;
};
// The rate of `axis` for `block` on its controller (caps, rateSpec: the controller's feed-rate
// parameter spec, null when not known; known: what the device holds). An axis at F runs at
// most at its ceiling; where the block carries resolved rates (ProgramBlock::axisRates: G93,
// or the shares of F on a coordinating controller) every axis of the controller is slowed by
// the same factor, as LinuxCNC slows the whole move. A share (G94) then stays within the
// parameter's range: below its minimum it runs at it (it arrives a little early), above its
// maximum (a feed override) at it.
AxisRate axisRate(const machine::MachineDescription& d, const machine::MachineAxis& axis,
                  const Capabilities& caps, const ParameterSpec* rateSpec,
                  const ParameterSet& known, const ProgramBlock& block);

// The feed (the move's unit/s) a contour move runs at in `stream`: its feed, or where that needs
// more than one step per tick on some axis, the highest its tick allows
// (motion::ContourSteps::highestFeed), a hair below so that the stream takes it. Refuse: the
// move's feed as it is (the check refuses it).
double contourFeed(const ContourMoves::Stream& stream, const motion::CanonicalMove& move,
                   machine::LimitPolicy limits);

} // namespace FeedLimit
} // namespace stepdeck::program
