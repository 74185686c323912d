#include "RunFromLine.h"
#include "ProgramReader.h"

namespace stepdeck::program {

namespace {
bool isSpindle(BlockKind k)
{
    return k == BlockKind::SpindleOn || k == BlockKind::SpindleReverse ||
           k == BlockKind::SpindleOff;
}

bool isCoolant(BlockKind k)
{
    return k == BlockKind::CoolantMist || k == BlockKind::CoolantFlood ||
           k == BlockKind::CoolantOff;
}
} // namespace

RunFromState RunFromState::before(ProgramReader& reader, int first)
{
    RunFromState state;
    for (int i = 0; i < first; ++i) {
        const ProgramBlock* b = reader.at(i);
        if (!b)
            break;
        // A line's own switch (M3 beside a move) and its action, in that order.
        for (const std::optional<BlockKind> k :
             {b->switchFirst, std::optional<BlockKind>(b->kind)}) {
            if (!k)
                continue;
            if (isSpindle(*k))
                state.spindle = *k;
            else if (isCoolant(*k))
                state.coolant = *k;
            else if (*k == BlockKind::ToolChange)
                state.tool = b->number;
            else if (*k == BlockKind::End)
                state = RunFromState{}; // LinuxCNC's M2: spindle and coolant off
        }
        state.rpm = b->rpm;
    }
    if (const ProgramBlock* start = reader.at(first))
        state.rpm = start->rpm; // the S in effect where the run starts
    return state;
}

QList<ProgramBlock> RunFromState::switches(int line) const
{
    QList<ProgramBlock> out;
    if (spindle && *spindle != BlockKind::SpindleOff) {
        ProgramBlock b;
        b.line = line;
        b.kind = *spindle;
        b.rpm = rpm;
        b.text = QStringLiteral("%1 S%2").arg(blockWord(b.kind), figure(rpm));
        out << b;
    }
    if (coolant && *coolant != BlockKind::CoolantOff) {
        ProgramBlock b;
        b.line = line;
        b.kind = *coolant;
        b.text = blockWord(b.kind);
        out << b;
    }
    return out;
}

QString RunFromState::text() const
{
    QStringList parts;
    if (spindle && *spindle != BlockKind::SpindleOff)
        parts << tr("spindle on at S%1 (%2)")
                     .arg(figure(rpm), *spindle == BlockKind::SpindleReverse
                                           ? QStringLiteral("M4")
                                           : QStringLiteral("M3"));
    if (coolant && *coolant != BlockKind::CoolantOff)
        parts << tr("coolant on (%1)")
                     .arg(*coolant == BlockKind::CoolantMist ? QStringLiteral("M7")
                                                             : QStringLiteral("M8"));
    if (tool > 0)
        parts << tr("tool %1 loaded").arg(tool);
    return parts.join(QStringLiteral(", "));
}

} // namespace stepdeck::program
