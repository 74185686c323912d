// libFuzzer target "program_parse" (issue 20): the motion program parser (ProgramParser) on
// any bytes. Invariants: no crash or undefined behaviour; a program comes back exactly when
// there is no error; every error names a line and column within the input; the same bytes
// fed in the input's own chunks give the same result; blocks stand in line order, and every
// repeat's partner points back to it.
#include "FuzzSupport.h"
#include "program/ProgramParser.h"

using namespace stepdeck::program;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray text = fuzz::input(data, size);
    const QStringList axes{"X", "Y", "Z", "A", "U"};
    QList<ProgramError> errors;
    const std::optional<Program> whole = ProgramParser::parse(text, axes, &errors);
    FUZZ_CHECK(whole.has_value() == errors.isEmpty(), QString::number(errors.size()));
    const int lines = int(text.count('\n')) + 1;
    for (const ProgramError& e : errors) {
        FUZZ_CHECK(e.line >= 1 && e.line <= lines && e.column >= 1, e.text());
        FUZZ_CHECK(!e.message.isEmpty(), e.text());
    }
    FUZZ_CHECK(errors.size() <= ProgramParser::kMaxErrors + 1, QString::number(errors.size()));

    ProgramParser chunked(axes);
    for (const QByteArray& chunk : fuzz::split(text))
        chunked.feed(chunk);
    QList<ProgramError> chunkErrors;
    const std::optional<Program> again = chunked.finish(&chunkErrors);
    FUZZ_CHECK(chunkErrors == errors, QStringLiteral("chunked errors differ"));
    FUZZ_CHECK(again.has_value() == whole.has_value(), QStringLiteral("chunked result differs"));
    if (!whole)
        return 0;
    FUZZ_CHECK(again->blocks == whole->blocks, QStringLiteral("chunked blocks differ"));
    int previous = 0;
    for (qsizetype i = 0; i < whole->blocks.size(); ++i) {
        const ProgramBlock& b = whole->blocks.at(i);
        FUZZ_CHECK(b.line > previous, QString::number(b.line));
        previous = b.line;
        if (b.kind == BlockKind::RepeatStart || b.kind == BlockKind::RepeatEnd) {
            FUZZ_CHECK(b.partner >= 0 && b.partner < whole->blocks.size(), b.text);
            FUZZ_CHECK(whole->blocks.at(b.partner).partner == i, b.text);
        }
        if (b.kind == BlockKind::RepeatStart)
            FUZZ_CHECK(b.count >= 0 && b.count <= ProgramParser::kMaxRepeat, b.text);
    }
    return 0;
}
