#pragma once
#include "Soak.h"
#include "sim/Simulator.h"
#include <QList>
#include <QPair>

namespace stepdeck::bench {

constexpr int kMoveWindow = 200; // soak move sizes repeat only after this many moves

// One move the soak commanded on one device axis, and what the host was told of it.
struct CommandedMove
{
    Axis axis;
    qint64 steps;
    bool ok;           // the host was told it succeeded
    int journalBefore; // the device journal's size when the command was sent
};

// Matches one device's journal (Simulator::acceptedMoves) against the moves commanded on it
// and adds the counts to *fig: deviceMoves, jogMoves, hostMovesOk, lostMoves, duplicatedMoves,
// unconfirmedMoves, unmatchedDeviceMoves. `jogRanges` are journal index ranges [first, end)
// made by jogs of models that jog by targets; they are counted apart and not matched.
void matchMoves(const QList<SimulatedMove>& journal, const QList<CommandedMove>& commanded,
                const QList<QPair<int, int>>& jogRanges, SoakFigures* fig);

} // namespace stepdeck::bench
