#include "FeedLimit.h"
#include "motion/ContourSteps.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program::FeedLimit {

namespace {

// How far below the tick's highest feed a limited contour move runs: ContourSteps refuses a
// move that needs more than its tick, and the highest feed is a quotient in floating point.
constexpr double kBelowHighest = 1.0 - 1e-9;

} // namespace

double contourFeed(const ContourMoves::Stream& stream, const motion::CanonicalMove& move,
                   machine::LimitPolicy limits)
{
    if (limits != machine::LimitPolicy::Clamp || stream.tickRate <= 0 || move.feed <= 0 ||
        move.length() <= 0)
        return move.feed;
    if (motion::ContourSteps::neededTickRate(move, stream.scale) <= stream.tickRate)
        return move.feed;
    return std::min(move.feed,
                    motion::ContourSteps::highestFeed(move, stream.scale, stream.tickRate) *
                        kBelowHighest);
}

} // namespace stepdeck::program::FeedLimit
