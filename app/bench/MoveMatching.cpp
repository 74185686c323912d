#include "MoveMatching.h"
#include <cstdio>

namespace stepdeck::bench {

namespace {
// Journal indices of the moves made by commands; moves inside a jog range are counted apart.
QList<int> commandMoveIndices(int journalSize, const QList<QPair<int, int>>& jogRanges,
                              SoakFigures* fig)
{
    QList<int> indices;
    int r = 0;
    for (int j = 0; j < journalSize; ++j) {
        while (r < jogRanges.size() && j >= jogRanges.at(r).second)
            ++r;
        if (r < jogRanges.size() && j >= jogRanges.at(r).first)
            ++fig->jogMoves;
        else
            indices << j;
    }
    return indices;
}

// STEPDECK_SOAK_VERBOSE: the first unmatched device moves with the commands around them.
void reportUnmatched(Axis axis, int j, const SimulatedMove& d, const QList<CommandedMove>& wanted,
                     int next, qint64 unmatchedSoFar)
{
    static const bool verbose = qEnvironmentVariableIsSet("STEPDECK_SOAK_VERBOSE");
    if (!verbose || unmatchedSoFar > 20)
        return;
    QString line = QStringLiteral("unmatched: axis %1, journal %2, steps %3; commands:")
                       .arg(axisName(axis))
                       .arg(j)
                       .arg(d.steps);
    for (int i = qMax(0, next - 3); i < qMin(int(wanted.size()), next + 3); ++i)
        line += QStringLiteral(" [%1%2 %3 %4@%5]")
                    .arg(i == next ? QStringLiteral(">") : QString())
                    .arg(i)
                    .arg(wanted[i].steps)
                    .arg(wanted[i].ok ? QStringLiteral("ok") : QStringLiteral("failed"))
                    .arg(wanted[i].journalBefore);
    line += QLatin1Char('\n');
    std::fputs(qPrintable(line), stderr);
}

// One axis: how often the device started each of the moves commanded on it.
QList<int> startsPerCommand(Axis axis, const QList<SimulatedMove>& journal,
                            const QList<int>& indices, const QList<CommandedMove>& wanted,
                            SoakFigures* fig)
{
    QList<int> starts(wanted.size(), 0);
    int next = 0;
    for (int j : indices) {
        const SimulatedMove& d = journal.at(j);
        if (d.axis != axis)
            continue;
        // Commands sent before the device journaled this move, within the window.
        const auto candidate = [&](int k) {
            return k < wanted.size() && k < next + kMoveWindow && wanted[k].journalBefore <= j;
        };
        int k = next;
        while (candidate(k) && wanted[k].steps != d.steps)
            ++k;
        if (next > 0 && wanted[next - 1].steps == d.steps) {
            ++starts[next - 1]; // the previous move once more
        } else if (candidate(k) && wanted[k].steps == d.steps) {
            ++starts[k];
            next = k + 1;
        } else {
            ++fig->unmatchedDeviceMoves;
            reportUnmatched(axis, j, d, wanted, next, fig->unmatchedDeviceMoves);
        }
    }
    return starts;
}
} // namespace

// Per axis, in order: every device move matches the next commanded move of that size (moves
// in between were not started); one commanded move started twice is a duplicate. A device
// move can only stand for a command sent before the device journaled it: without that bound
// one device move that stands for no command (e.g. a late jog chunk) matched a command of the
// same size up to kMoveWindow moves later, and every move after it then counted as lost and
// unmatched.
void matchMoves(const QList<SimulatedMove>& journal, const QList<CommandedMove>& commanded,
                const QList<QPair<int, int>>& jogRanges, SoakFigures* fig)
{
    const QList<int> indices = commandMoveIndices(int(journal.size()), jogRanges, fig);
    fig->deviceMoves += indices.size();
    QMap<Axis, bool> commandedAxes; // every axis a command went to, in axis order
    for (const CommandedMove& c : commanded)
        commandedAxes.insert(c.axis, true);
    for (Axis axis : commandedAxes.keys()) {
        QList<CommandedMove> wanted;
        for (const CommandedMove& c : commanded) {
            if (c.axis == axis)
                wanted << c;
        }
        const QList<int> starts = startsPerCommand(axis, journal, indices, wanted, fig);
        for (int i = 0; i < wanted.size(); ++i) {
            fig->hostMovesOk += wanted[i].ok ? 1 : 0;
            fig->lostMoves += wanted[i].ok && starts[i] == 0 ? 1 : 0;
            fig->duplicatedMoves += qMax(0, starts[i] - 1);
            fig->unconfirmedMoves += !wanted[i].ok && starts[i] > 0 ? 1 : 0;
        }
    }
}

} // namespace stepdeck::bench
