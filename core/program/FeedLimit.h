#pragma once
#include "ContourMoves.h"
#include "machine/MachineDescription.h"
#include "motion/CanonicalMove.h"

namespace stepdeck::program {

// Limits as LinuxCNC and GRBL apply them (issue 50, docs/programs.md "Limits"): a feed above
// the highest a move can run at runs at that highest (LinuxCNC limits a move's velocity to its
// axes' maximum velocities, GRBL to its $110..$112; neither refuses). What a device cannot do
// more slowly is not limited here: the check refuses it. Here: a contour move's feed, the one
// place the check (its note, its time estimate and preview) and the run (the contour it
// streams) take it from. A move of its own is limited by motion::MoveRates, an S by
// motion::SwitchExecutor. With the machine file's "limits":
// "refuse" (machine::LimitPolicy::Refuse) nothing is limited and the check refuses such feeds as
// it did before issue 50. Pure.
namespace FeedLimit {

// The feed (the move's unit/s) a contour move runs at in `stream`: its feed, or where that needs
// more than one step per tick on some axis, the highest its tick allows
// (motion::ContourSteps::highestFeed), a hair below so that the stream takes it. Refuse: the
// move's feed as it is (the check refuses it).
double contourFeed(const ContourMoves::Stream& stream, const motion::CanonicalMove& move,
                   machine::LimitPolicy limits);

} // namespace FeedLimit
} // namespace stepdeck::program
