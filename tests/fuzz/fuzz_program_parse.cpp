// libFuzzer target "program_parse" (issue 20): the motion program parser (ProgramParser) on
// any bytes. Invariants: no crash or undefined behaviour; a program comes back exactly when
// there is no error; every error names a line and column within the input; the same bytes
// fed in the input's own chunks give the same result; blocks stand in line order, and every
// repeat's partner points back to it. The blocks of an accepted program are then walked as the
// check and the run follow them (issue 29): the current point through ProgramCoordinates,
// G2/G3 through ArcPath, drilling cycles through DrillCycle, G93's rates through InverseTime,
// on a mill in millimetres; the same bytes are read as a tool table, which writes back to
// itself.
#include "FuzzSupport.h"
#include "program/ArcPath.h"
#include "program/DrillCycle.h"
#include "program/InverseTime.h"
#include "program/ProgramCoordinates.h"
#include "program/ProgramParser.h"
#include "program/ProgramUnits.h"
#include "program/ToolTable.h"
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;

namespace {

machine::MachineDescription mill()
{
    machine::MachineDescription d;
    const char* names[] = {"X", "Y", "Z", "A", "U"};
    for (int i = 0; i < 5; ++i) {
        machine::MachineAxis a;
        a.name = QLatin1String(names[i]);
        a.controller = QStringLiteral("table");
        a.axis = Axis::at(i % 4);
        a.unit = i == 3 ? machine::AxisUnit::Degree : machine::AxisUnit::Millimetre;
        a.stepsPerUnit = 100;
        d.axes << a;
    }
    return d;
}

// Every block in file order (repeats once): the paths an arc and a cycle plan from the
// current point stay finite, bounded, and end where they say.
void walk(const Program& program)
{
    static const machine::MachineDescription d = mill();
    CoordinateSystems systems;
    systems[1] = {{QStringLiteral("X"), 5.0}};
    ProgramCoordinates coordinates(systems, 0, *ToolTable::parse("T1 Z2.5 ;one\n", nullptr));
    AxisPositions at(size_t(d.axes.size()), 0.0);
    for (const ProgramBlock& b : program.allBlocks()) {
        const QMap<QString, double> offsets = coordinates.offsets(b, d);
        if (isArc(b.kind)) {
            const auto planned = ArcPath::plan(b, d, at, offsets);
            if (const ArcPath* arc = std::get_if<ArcPath>(&planned)) {
                FUZZ_CHECK(arc->chords() >= 1 && arc->chords() <= ArcPath::kMaxChords, b.text);
                for (const auto& [axis, value] : arc->end()) {
                    FUZZ_CHECK(std::isfinite(value), b.text);
                    at[size_t(axis)] = value;
                }
            }
        } else if (b.kind == BlockKind::DrillCycle) {
            const auto planned = DrillCycle::plan(b, d, at, offsets);
            if (const DrillCycle* cycle = std::get_if<DrillCycle>(&planned)) {
                FUZZ_CHECK(cycle->segments().size() <= size_t(DrillCycle::kMaxSegments), b.text);
                for (const auto& [axis, value] : cycle->end()) {
                    FUZZ_CHECK(std::isfinite(value), b.text);
                    at[size_t(axis)] = value;
                }
            }
        } else {
            if (b.inverseTime) {
                // G93: a rate above 0 per moving axis (infinite for a huge distance times F:
                // out of every controller's range, units::feedStepsPerSecond), never NaN.
                const ProgramBlock r = InverseTime::resolve(b, d, at, offsets);
                for (auto it = r.axisRates.cbegin(); it != r.axisRates.cend(); ++it) {
                    FUZZ_CHECK(it.value() > 0, b.text);
                    FUZZ_CHECK(units::feedStepsPerSecond(d.axes.first(), it.value(), false) >= 1,
                               b.text);
                }
            }
            coordinates.apply(b, d, at);
            coordinates.advance(b, d, &at);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray text = fuzz::input(data, size);
    const QStringList axes{"X", "Y", "Z", "A", "U"};
    QList<ProgramError> errors;
    const std::optional<Program> whole = ProgramParser::parse(text, axes, &errors);
    if (const std::optional<ToolTable> tools = ToolTable::parse(text, nullptr)) {
        const std::optional<ToolTable> again = ToolTable::parse(tools->text(), nullptr);
        FUZZ_CHECK(again && again->text() == tools->text(), QStringLiteral("tool table"));
    }
    FUZZ_CHECK(whole.has_value() == errors.isEmpty(), QString::number(errors.size()));
    const int lines = int(text.count('\n')) + 1;
    for (const ProgramError& e : errors) {
        FUZZ_CHECK(e.line >= 1 && e.line <= lines && e.column >= 1, e.text());
        FUZZ_CHECK(!e.message.isEmpty(), e.text());
    }
    FUZZ_CHECK(errors.size() <= ProgramParser::kMaxErrors + 1, QString::number(errors.size()));

    ProgramParser chunked(axes);
    QList<ProgramBlock> streamed; // as the parser gives them out while it reads
    chunked.setSink([&streamed](ProgramBlock&& b) { streamed << b; });
    for (const QByteArray& chunk : fuzz::split(text))
        chunked.feed(chunk);
    QList<ProgramError> chunkErrors;
    const std::optional<Program> again = chunked.finish(&chunkErrors);
    FUZZ_CHECK(chunkErrors == errors, QStringLiteral("chunked errors differ"));
    FUZZ_CHECK(again.has_value() == whole.has_value(), QStringLiteral("chunked result differs"));
    if (!whole)
        return 0;
    // Read back through the index: the blocks the parser gave out (a RepeatStart's partner is
    // known only once its endrepeat is read).
    const QList<ProgramBlock> blocks = whole->allBlocks();
    FUZZ_CHECK(blocks.size() == streamed.size(), QStringLiteral("read back: other size"));
    for (qsizetype i = 0; i < blocks.size(); ++i) {
        ProgramBlock s = streamed.at(i);
        if (s.kind == BlockKind::RepeatStart)
            s.partner = blocks.at(i).partner;
        FUZZ_CHECK(s == blocks.at(i), QStringLiteral("read back: block %1 differs").arg(i));
    }
    int previous = 0;
    for (qsizetype i = 0; i < blocks.size(); ++i) {
        const ProgramBlock& b = blocks.at(i);
        // A line of several actions gives a block each (issue 50, LinuxCNC's whole line).
        FUZZ_CHECK(b.line >= previous && b.line >= 1, QString::number(b.line));
        previous = b.line;
        if (b.kind == BlockKind::RepeatStart || b.kind == BlockKind::RepeatEnd) {
            FUZZ_CHECK(b.partner >= 0 && b.partner < blocks.size(), b.text);
            FUZZ_CHECK(blocks.at(b.partner).partner == i, b.text);
        }
        if (b.kind == BlockKind::RepeatStart)
            FUZZ_CHECK(b.count >= 0 && b.count <= ProgramParser::kMaxRepeat, b.text);
    }
    walk(*whole);
    return 0;
}
