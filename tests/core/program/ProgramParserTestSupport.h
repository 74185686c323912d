#pragma once
// What the parser's tests share (tst_programparser, tst_programparserdialect): the axes they
// parse for and blocks and errors as text.
#include "program/ProgramParser.h"
#include <QStringList>

namespace stepdeck::program::parsertest {

inline const QStringList kAxes{"X", "Y", "Z", "A"};

// A block in one line: "G0 X=10 Y=5 abs mm F-" and the action's values.
inline QString describe(const ProgramBlock& b)
{
    QStringList out{blockWord(b.kind).isEmpty() ? QStringLiteral("modal") : blockWord(b.kind)};
    for (auto it = b.axes.cbegin(); it != b.axes.cend(); ++it)
        out << QStringLiteral("%1=%2").arg(it.key()).arg(it.value());
    out << (b.relative ? QStringLiteral("rel") : QStringLiteral("abs"));
    out << (b.inches ? QStringLiteral("in") : QStringLiteral("mm"));
    out << (b.feed ? QStringLiteral("F%1").arg(*b.feed) : QStringLiteral("F-"));
    switch (b.kind) {
    case BlockKind::Dwell:
        out << QStringLiteral("%1s").arg(b.seconds);
        break;
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
        out << QStringLiteral("%1rpm").arg(b.rpm);
        break;
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
        out << QStringLiteral("P%1").arg(b.number);
        break;
    case BlockKind::WaitInput:
        out << QStringLiteral("P%1 %2 %3s")
                   .arg(b.number)
                   .arg(b.inputHigh ? QStringLiteral("high") : QStringLiteral("low"))
                   .arg(b.seconds);
        break;
    case BlockKind::Pause:
    case BlockKind::OptionalPause:
        out << QStringLiteral("\"%1\"").arg(b.prompt);
        break;
    case BlockKind::ToolChange:
        out << QStringLiteral("T%1 \"%2\"").arg(b.number).arg(b.prompt);
        break;
    case BlockKind::RepeatStart:
        out << QStringLiteral("x%1").arg(b.count);
        break;
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise: {
        const QString plane[] = {QStringLiteral("G17"), QStringLiteral("G18"),
                                 QStringLiteral("G19")};
        out << plane[int(b.plane)];
        const auto word = [&](const char* l, const std::optional<double>& v) {
            if (v)
                out << QStringLiteral("%1%2").arg(QLatin1String(l)).arg(*v);
        };
        word("I", b.arc.i);
        word("J", b.arc.j);
        word("K", b.arc.k);
        word("R", b.arc.radius);
        out << QStringLiteral("P%1").arg(b.arc.turns);
        if (b.arc.centreAbsolute)
            out << QStringLiteral("G90.1");
        break;
    }
    default:
        break;
    }
    if (b.kind == BlockKind::SetCoordinates)
        out << QStringLiteral("P%1 %2").arg(b.number).arg(b.fromPosition ? "L20" : "L2");
    if (b.coordinateSystem >= 0)
        out << QStringLiteral("G%1").arg(54 + b.coordinateSystem);
    if (b.machineCoordinates)
        out << QStringLiteral("G53");
    if (b.lengthTool >= 0)
        out << QStringLiteral("H%1").arg(b.lengthTool);
    if (b.appliesLengthOffset)
        out << QStringLiteral("G43");
    if (!b.message.isEmpty())
        out << QStringLiteral("msg\"%1\"").arg(b.message);
    return out.join(QLatin1Char(' '));
}

inline QStringList describeAll(const Program& p)
{
    QStringList out;
    for (const ProgramBlock& b : p.allBlocks())
        out << QStringLiteral("%1: %2").arg(b.line).arg(describe(b));
    return out;
}

inline QStringList texts(const QList<ProgramError>& errors)
{
    QStringList out;
    for (const ProgramError& e : errors)
        out << e.text();
    return out;
}

} // namespace stepdeck::program::parsertest
