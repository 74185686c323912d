#include "ProgramBlock.h"

namespace stepdeck::program {

QString blockWord(BlockKind kind)
{
    switch (kind) {
    case BlockKind::Modal:
        return QString();
    case BlockKind::Rapid:
        return QStringLiteral("G0");
    case BlockKind::Feed:
        return QStringLiteral("G1");
    case BlockKind::ArcClockwise:
        return QStringLiteral("G2");
    case BlockKind::ArcCounterClockwise:
        return QStringLiteral("G3");
    case BlockKind::Home:
        return QStringLiteral("G28");
    case BlockKind::Dwell:
        return QStringLiteral("G4");
    case BlockKind::Pause:
        return QStringLiteral("M0");
    case BlockKind::OptionalPause:
        return QStringLiteral("M1");
    case BlockKind::ToolChange:
        return QStringLiteral("M6");
    case BlockKind::End:
        return QStringLiteral("M2");
    case BlockKind::SpindleOn:
        return QStringLiteral("M3");
    case BlockKind::SpindleReverse:
        return QStringLiteral("M4");
    case BlockKind::SpindleOff:
        return QStringLiteral("M5");
    case BlockKind::SpindleSpeed:
        return QStringLiteral("S");
    case BlockKind::CoolantMist:
        return QStringLiteral("M7");
    case BlockKind::CoolantFlood:
        return QStringLiteral("M8");
    case BlockKind::CoolantOff:
        return QStringLiteral("M9");
    case BlockKind::OutputOn:
        return QStringLiteral("M64");
    case BlockKind::OutputOff:
        return QStringLiteral("M65");
    case BlockKind::WaitInput:
        return QStringLiteral("M66");
    case BlockKind::SetCoordinates:
        return QStringLiteral("G10");
    case BlockKind::AxisOffset:
        return QStringLiteral("G92");
    case BlockKind::AxisOffsetReset:
        return QStringLiteral("G92.1");
    case BlockKind::AxisOffsetSuspend:
        return QStringLiteral("G92.2");
    case BlockKind::AxisOffsetRestore:
        return QStringLiteral("G92.3");
    case BlockKind::DrillCycle:
        return QStringLiteral("G81"); // blockWord(block) names the cycle's own code
    case BlockKind::RepeatStart:
        return QStringLiteral("O repeat");
    case BlockKind::RepeatEnd:
        return QStringLiteral("O endrepeat");
    }
    return QString();
}

QString blockWord(const ProgramBlock& block)
{
    if (block.kind == BlockKind::DrillCycle)
        return QStringLiteral("G%1").arg(block.cycle.code);
    return blockWord(block.kind);
}

QString figure(double value)
{
    QString text = QString::number(value, 'f', 3);
    while (text.endsWith(QLatin1Char('0')))
        text.chop(1);
    if (text.endsWith(QLatin1Char('.')))
        text.chop(1);
    return text == QLatin1String("-0") ? QStringLiteral("0") : text;
}

int ProgramBlock::columnOf(const QString& word) const
{
    if (const auto it = columns.constFind(word); it != columns.cend())
        return it.value();
    return actionColumn > 0 ? actionColumn : 1;
}

bool ProgramBlock::operator==(const ProgramBlock& o) const
{
    return line == o.line && text == o.text && kind == o.kind && axes == o.axes &&
           relative == o.relative && inches == o.inches && feed == o.feed &&
           inverseTime == o.inverseTime && axisRates == o.axisRates && plane == o.plane &&
           pathMode == o.pathMode && pathTolerance == o.pathTolerance && seconds == o.seconds &&
           number == o.number && inputHigh == o.inputHigh && rpm == o.rpm &&
           spindleChange == o.spindleChange && prompt == o.prompt && arc == o.arc &&
           cycle == o.cycle && coordinateSystem == o.coordinateSystem &&
           machineCoordinates == o.machineCoordinates && fromPosition == o.fromPosition &&
           lengthTool == o.lengthTool && appliesLengthOffset == o.appliesLengthOffset &&
           comp == o.comp && message == o.message && oNumber == o.oNumber && count == o.count &&
           partner == o.partner && columns == o.columns && actionColumn == o.actionColumn;
}

QString ProgramError::text() const
{
    return QStringLiteral("%1:%2: %3").arg(line).arg(column).arg(message);
}

} // namespace stepdeck::program
