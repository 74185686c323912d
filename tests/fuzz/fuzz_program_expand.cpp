// libFuzzer target "program_expand" (issue 33): programs in LinuxCNC's language (parameters,
// expressions, O-word subroutines, branches and loops, (DEBUG, …)) worked out into ordinary
// lines (ProgramExpansion, NgcInterpreter), then parsed as the check parses them
// (ProgramReader over the worked-out text and its line map). Invariants: no crash, undefined
// behaviour or leak; the text uses the language alike read whole or through a source reader; a
// result comes back exactly when there is no error; every error names a source line (and a
// column within it) and says why; the same bytes work out to the same text, map and errors; the
// worked-out text is plain G-code (no '#' or '[' outside comments but in GRBL's "$" lines, no
// O-word lines, nothing ProgramExpansion would work out again); every worked-out line maps to a
// source line, in source order when there are no O words; the parser's errors and blocks name
// source lines, no block is a repeat (the interpreter ran them), and the blocks read back through
// the index are those the parser gave out in chunks.
//
// The time an input takes: the interpreter's bounds are lowered (NgcContext::limits, below),
// so a runaway loop of a few bytes ends in milliseconds, with the error naming its line, instead
// of the minutes the full bounds allow under the sanitizers (docs/fuzzing.md).
#include "FuzzSupport.h"
#include "program/ProgramParser.h"
#include "program/ProgramReader.h"
#include "program/language/ProgramExpansion.h"
#include <QDir>

using namespace stepdeck;
using namespace stepdeck::program;

namespace {

NgcContext context()
{
    NgcContext c;
    c.limits = NgcLimits{1000, 200000, 20000}; // passes, lines run, lines given out
    c.coordinateSystems[0] = {{QStringLiteral("X"), 1.5}, {QStringLiteral("Z"), -2.0}};
    c.coordinateSystems[1] = {{QStringLiteral("X"), 5.0}};
    c.activeSystem = 0;
    return c; // no subroutine folder: the target reads no files
}

// The source's lines as ProgramExpansion counts them: a UTF-8 byte-order mark left out, and a
// last newline ends the last line rather than starting an empty one.
QList<QByteArray> sourceLines(const QByteArray& text)
{
    QByteArray body = text.startsWith("\xEF\xBB\xBF") ? text.mid(3) : text;
    if (body.endsWith('\n'))
        body.chop(1);
    return body.split('\n');
}

// The worked-out text outside comments ("( … )" and "; …").
QString withoutComments(const QString& line)
{
    QString out;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (c == QLatin1Char(';'))
            break;
        if (c == QLatin1Char('(')) {
            const qsizetype close = line.indexOf(QLatin1Char(')'), i);
            if (close < 0)
                break;
            i = close;
            continue;
        }
        out += c;
    }
    return out;
}

struct Expanded
{
    std::optional<ProgramExpansion::Result> result;
    QList<ProgramError> errors;
    QByteArray text;         // the worked-out text (empty when refused)
    QList<int> sourceLineOf; // [n - 1]: the source line of worked-out line n
};

Expanded expand(const QByteArray& input)
{
    Expanded e;
    e.result = ProgramExpansion::expand(ProgramSource::bytes(input), context(), &e.errors);
    if (!e.result)
        return e;
    ProgramSourceReader reader(e.result->source);
    QString why;
    FUZZ_CHECK(reader.open(&why), why);
    e.text = reader.read(0, reader.size(), &why);
    FUZZ_CHECK(why.isEmpty() && e.text.size() == reader.size(), why);
    FUZZ_CHECK(e.result->info && e.result->info->lines, QStringLiteral("no line map"));
    FUZZ_CHECK(e.text.isEmpty() || e.text.endsWith('\n'), QStringLiteral("last line open"));
    const qsizetype lines = e.text.count('\n');
    e.sourceLineOf.reserve(lines);
    for (int n = 1; n <= lines; ++n)
        e.sourceLineOf << e.result->info->lines->sourceLine(n);
    return e;
}

// The worked-out text parsed as the check parses it (one pass, then read back through the
// index), and once more in chunks.
void parse(const Expanded& e, int lineCount)
{
    const std::shared_ptr<const NgcLineMap>& map = e.result->info->lines;
    const QStringList axes{"X", "Y", "Z", "A", "U"};
    ProgramReader reader(e.result->source, axes, map);
    QList<ProgramError> errors;
    const std::optional<Program> program = reader.finish(&errors);
    FUZZ_CHECK(program.has_value() == errors.isEmpty(), QString::number(errors.size()));
    FUZZ_CHECK(errors.size() <= ProgramParser::kMaxErrors + 1, QString::number(errors.size()));
    for (const ProgramError& error : errors) {
        FUZZ_CHECK(error.line >= 1 && error.line <= lineCount && error.column >= 1, error.text());
        FUZZ_CHECK(!error.message.trimmed().isEmpty(), error.text());
    }

    ProgramParser chunked(axes);
    chunked.setLineMap(map);
    QList<ProgramBlock> streamed;
    chunked.setSink([&streamed](ProgramBlock&& b) { streamed << b; });
    for (const QByteArray& chunk : fuzz::split(e.text)) // lengths 1..16, drawn from the text
        chunked.feed(chunk);
    QList<ProgramError> chunkErrors;
    const std::optional<Program> again = chunked.finish(&chunkErrors);
    FUZZ_CHECK(chunkErrors == errors, QStringLiteral("chunked errors differ"));
    if (!program)
        return;
    FUZZ_CHECK(again.has_value(), QStringLiteral("chunked result differs"));
    FUZZ_CHECK(
        program->lines == e.sourceLineOf.size(),
        QStringLiteral("%1 lines parsed of %2").arg(program->lines).arg(e.sourceLineOf.size()));
    FUZZ_CHECK(
        streamed.size() == program->blockCount,
        QStringLiteral("%1 blocks, %2 given out").arg(program->blockCount).arg(streamed.size()));

    ProgramReader back(*program); // read back from the index's checkpoints
    for (int i = 0; i < program->blockCount; ++i) {
        const ProgramBlock* b = back.at(i);
        FUZZ_CHECK(b, QStringLiteral("block %1 not read back: %2").arg(i).arg(back.error()));
        FUZZ_CHECK(*b == streamed.at(i), QStringLiteral("block %1 read back differs").arg(i));
        FUZZ_CHECK(b->line >= 1 && b->line <= lineCount, QString::number(b->line) + ": " + b->text);
        FUZZ_CHECK(b->kind != BlockKind::RepeatStart && b->kind != BlockKind::RepeatEnd, b->text);
    }
    FUZZ_CHECK(!back.at(program->blockCount), QStringLiteral("a block past the last"));
    FUZZ_CHECK(back.error().isEmpty(), back.error());
}

void check(const QByteArray& text)
{
    QString why;
    const std::optional<bool> uses =
        ProgramExpansion::usesLanguage(ProgramSource::bytes(text), &why);
    FUZZ_CHECK(uses.has_value(), why);
    FUZZ_CHECK(*uses == ProgramExpansion::usesLanguage(QByteArrayView(text)),
               QStringLiteral("usesLanguage: the source reader and the bytes differ"));

    const QList<QByteArray> source = sourceLines(text);
    const int lineCount = int(source.size());
    const Expanded first = expand(text);
    FUZZ_CHECK(first.result.has_value() == first.errors.isEmpty(),
               QString::number(first.errors.size()));
    FUZZ_CHECK(first.errors.size() <= 100, QString::number(first.errors.size()));
    for (const ProgramError& e : first.errors) {
        FUZZ_CHECK(e.line >= 1 && e.line <= lineCount, e.text());
        // Columns count UTF-16 units of the line as the interpreter read it.
        const qsizetype length = QString::fromUtf8(source.at(e.line - 1)).size();
        FUZZ_CHECK(e.column >= 1 && e.column <= length + 1, e.text());
        FUZZ_CHECK(!e.message.trimmed().isEmpty(), e.text());
    }

    // The same bytes again: the same result, byte for byte (no state kept between runs).
    const Expanded second = expand(text);
    FUZZ_CHECK(second.errors == first.errors, QStringLiteral("errors differ on a second run"));
    FUZZ_CHECK(second.text == first.text, QStringLiteral("text differs on a second run"));
    FUZZ_CHECK(second.sourceLineOf == first.sourceLineOf,
               QStringLiteral("line map differs on a second run"));
    if (!first.result)
        return;

    const ProgramExpansionInfo& info = *first.result->info;
    FUZZ_CHECK(info.sourceLines == lineCount,
               QStringLiteral("%1 source lines, counted %2").arg(info.sourceLines).arg(lineCount));
    FUZZ_CHECK(info.coordinateSystems == context().coordinateSystems &&
                   info.activeSystem == context().activeSystem,
               QStringLiteral("context not kept"));
    for (qsizetype n = 0; n < first.sourceLineOf.size(); ++n) {
        const int s = first.sourceLineOf.at(n);
        FUZZ_CHECK(s >= 1 && s <= lineCount,
                   QStringLiteral("worked-out line %1 -> source line %2 of %3")
                       .arg(n + 1)
                       .arg(s)
                       .arg(lineCount));
    }
    // Without O words the lines run once each, in their order.
    bool control = false;
    for (const QByteArray& l : source) {
        std::optional<ProgramError> broken;
        control = control || NgcStatement::read(QString::fromUtf8(l), 1, &broken).has_value();
    }
    for (qsizetype n = 1; n < first.sourceLineOf.size() && !control; ++n)
        FUZZ_CHECK(first.sourceLineOf.at(n) > first.sourceLineOf.at(n - 1),
                   QStringLiteral("worked-out line %1 -> source line %2, after %3")
                       .arg(n + 1)
                       .arg(first.sourceLineOf.at(n))
                       .arg(first.sourceLineOf.at(n - 1)));

    // Plain G-code: nothing of the language is left.
    const QList<QByteArray> out =
        first.text.isEmpty() ? QList<QByteArray>() : sourceLines(first.text);
    for (qsizetype n = 0; n < out.size(); ++n) {
        const QString line = QString::fromUtf8(out.at(n));
        const QString code = withoutComments(line);
        // GRBL's "$" lines go to the parser as written ("$#" is GRBL's parameter report).
        if (line.trimmed().startsWith(QLatin1Char('$')))
            continue;
        FUZZ_CHECK(!code.contains(QLatin1Char('#')) && !code.contains(QLatin1Char('[')),
                   QStringLiteral("worked-out line %1: %2").arg(n + 1).arg(line));
        // A Fanuc program number before the first block (issue 50) is passed to the parser,
        // which takes it as the program's name: no O word of the language.
        if (ProgramParser::programNumber(line.trimmed()))
            continue;
        std::optional<ProgramError> broken;
        const std::optional<NgcStatement> o = NgcStatement::read(line, int(n) + 1, &broken);
        FUZZ_CHECK(!o && !broken,
                   QStringLiteral("O word in worked-out line %1: %2").arg(n + 1).arg(line));
    }
    FUZZ_CHECK(!ProgramExpansion::usesLanguage(QByteArrayView(first.text)),
               QStringLiteral("the worked-out text uses the language"));

    parse(first, lineCount);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    check(fuzz::input(data, size));
    return 0;
}
