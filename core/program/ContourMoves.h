#pragma once
#include "ArcPath.h"
#include "ProgramCheck.h"
#include "ProgramUnits.h"
#include "motion/CanonicalMove.h"
#include "motion/ContourSteps.h"
#include "motion/executors/StreamExecutor.h"
#include <QCoreApplication>
#include <vector>

namespace stepdeck::program {

// Which feed blocks of a program run as one step stream, and the canonical moves they become
// (issue 30, docs/programs.md "Contours"). Shared by the check and the run, so that the check
// refuses what the run would: a block runs in a controller's stream when it is a G1, G2 or G3
// in G64 (LinuxCNC's blending mode, its default) with F per minute, and every axis it moves is
// on that one controller (Capabilities::contourStream) in one unit. The run joins such blocks
// into one stream until a block of another kind comes (a rapid, a dwell, an M word, a pause,
// the end); G61 and G61.1 keep LinuxCNC's stop at every programmed point, one block at a time.
class ContourMoves
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ContourMoves)
public:
    // A controller that runs contours as a step stream (the stream executor's layout).
    using Stream = motion::StepStream;

    explicit ContourMoves(const MachineFacts& facts);

    // The stream `block` runs in, or null (it runs on its own, as before issue 30).
    const Stream* streamOf(const ProgramBlock& block) const;
    const std::vector<Stream>& streams() const { return m_streams; }
    // The feed of `block` in its axes' unit per second.
    double feedPerSecond(const Stream& stream, const ProgramBlock& block) const;
    // The slots' positions at the current point; an unknown one counts from 0 (a relative move
    // from an unknown position: only the move's shape matters to the stream).
    motion::Position positionOf(const Stream& stream, const AxisPositions& current) const;
    // A G1 from `from`: absolute targets are work coordinates, offset(axis name) gives the
    // machine position of its work zero; relative ones are distances.
    template <typename Offset>
    motion::CanonicalMove lineMove(const Stream& stream, const ProgramBlock& block,
                                   const motion::Position& from, const Offset& offset) const
    {
        motion::CanonicalMove move = startMove(stream, block, from);
        for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
            const int slot = slotOf(it.key());
            if (slot < 0)
                continue;
            const machine::MachineAxis& axis =
                m_facts.description.axes.at(stream.axisOfSlot[size_t(slot)]);
            move.end[size_t(slot)] =
                *units::wordTarget(axis, it.value(), block.inches, block.relative,
                                   block.relative ? 0.0 : offset(it.key()), from[size_t(slot)]);
        }
        return move;
    }
    // A G2/G3 planned from `from` (ArcPath), as one arc of the stream: no chords.
    motion::CanonicalMove arcMove(const Stream& stream, const ProgramBlock& block,
                                  const ArcPath& path, const motion::Position& from) const;
    // Why the stream cannot run `move` at the block's F (the feed needs a faster tick than
    // the stream has), naming the highest F; empty when it can.
    QString feedRefusal(const Stream& stream, const motion::CanonicalMove& move,
                        const ProgramBlock& block) const;

private:
    int slotOf(const QString& axisName) const;
    motion::CanonicalMove startMove(const Stream& stream, const ProgramBlock& block,
                                    const motion::Position& from) const;

    const MachineFacts& m_facts;
    std::vector<Stream> m_streams;
    std::vector<int> m_streamOfAxis; // per machine axis: index into m_streams, -1: none
    std::vector<int> m_slotOfAxis;   // per machine axis: its slot in that stream
};

} // namespace stepdeck::program
