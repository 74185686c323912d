// ProgramReader and ProgramIndex (issue 29, "streamed, any length"): the blocks read back from
// the source through the sparse index are the blocks the parser gave out; a file changed since
// it was read is refused, never run; the check's one pass gives what the check of the parsed
// program gives, also where a repeat reads back more than the reader keeps.
#include "ProgramCheckTestSupport.h"
#include "TestMain.h"
#include "program/ProgramReader.h"
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

using namespace stepdeck::program;
using namespace stepdeck::program::checktest;

namespace {

const QStringList kReaderAxes{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};

// `lines` lines in the style of a CAM finishing pass, with what makes the index matter: modal
// words that change (G91/G90, F, G20/G21), comments and blank lines, and a repeat.
QByteArray longProgram(int lines)
{
    QByteArray text = "%\nG21 G90 G17 (header)\nG0 X0 Y0 Z5\n";
    int line = 3;
    for (; line < lines - 2; ++line) {
        if (line % 997 == 0)
            text += "\n";
        else if (line % 1499 == 0)
            text += "(pass " + QByteArray::number(line) + ")\n";
        else if (line % 3001 == 0) {
            text += "G91 G1 X0.1 F" + QByteArray::number(300 + line % 7) + "\nG90\n";
            ++line;
        } else
            text += "G1 X" + QByteArray::number((line % 400) * 0.25, 'f', 2) + " Y" +
                    QByteArray::number((line / 400) * 0.5, 'f', 1) + " F600\n";
    }
    text += "M2\n%\n";
    return text;
}

QList<ProgramBlock> streamedBlocks(const QByteArray& text, std::optional<Program>* program)
{
    QList<ProgramBlock> out;
    ProgramParser parser(kReaderAxes);
    parser.setSink([&out](ProgramBlock&& b) { out << b; });
    parser.feed(text);
    *program = parser.finish(nullptr);
    if (*program)
        (*program)->source = ProgramSource::bytes(text);
    return out;
}

// A mill whose table is 1000 mm long, so that the long programs stay inside it.
MachineFacts longMill()
{
    MachineFacts facts = machineFacts(QStringLiteral("mill"));
    for (MachineAxis& a : facts.description.axes) {
        a.softMinimum = -1000;
        a.softMaximum = 1000;
        facts.knownPositions.insert(a.name, 0.0);
    }
    return facts;
}

} // namespace

class TestProgramReader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void index_checkpointsEveryFewThousandLines();
    void at_anyOrder_theBlocksTheParserGaveOut();
    void at_blockDeleteEitherWay_readBackAsTheParserRead_data();
    void at_blockDeleteEitherWay_readBackAsTheParserRead();
    void at_fileChangedSinceRead_refusedWithReason_data();
    void at_fileChangedSinceRead_refusedWithReason();
    void firstBlockAtLine_andEnclosingRepeat_bothModes_data();
    void firstBlockAtLine_andEnclosingRepeat_bothModes();
    void check_onePass_sameAsParsedProgram_data();
    void check_onePass_sameAsParsedProgram();
    void check_progressCancels_nothingKnown();
    void bytesRead_overAProgram_followsTheBlocksReadBack();
    void check_onePassParseError_parserErrorsOnly();
};

// A check over a Program (the run's start, the CLI's --dry-run) reports its progress by how far
// the blocks it read back reach, not the file's length from the start.
void TestProgramReader::bytesRead_overAProgram_followsTheBlocksReadBack()
{
    const QByteArray text = longProgram(20000);
    std::optional<Program> p;
    const QList<ProgramBlock> blocks = streamedBlocks(text, &p);
    QVERIFY(p);
    ProgramReader reader(*p);
    QCOMPARE(reader.totalBytes(), qint64(text.size()));
    QCOMPARE(reader.bytesRead(), qint64(0));
    QVERIFY(reader.at(0));
    const qint64 first = reader.bytesRead();
    QVERIFY2(first > 0 && first < text.size() / 4, qPrintable(QString::number(first)));
    QVERIFY(reader.at(int(blocks.size()) / 2));
    const qint64 half = reader.bytesRead();
    QVERIFY2(half > first && half < text.size(), qPrintable(QString::number(half)));
    QVERIFY(reader.at(0)); // read back from the start: the farthest reach stays
    QCOMPARE(reader.bytesRead(), half);
    QVERIFY(reader.at(int(blocks.size()) - 1));
    QCOMPARE(reader.bytesRead(), qint64(text.size()));
}

void TestProgramReader::index_checkpointsEveryFewThousandLines()
{
    const QByteArray text = longProgram(20000);
    std::optional<Program> p;
    streamedBlocks(text, &p);
    QVERIFY(p);
    QCOMPARE(p->lines, 20000);
    // Line 0, then every kCheckpointLines lines: the index grows with the length / 2048.
    QCOMPARE(p->index->checkpoints.size(), size_t(1 + 20000 / ProgramIndex::kCheckpointLines));
    for (size_t c = 1; c < p->index->checkpoints.size(); ++c) {
        const ProgramCheckpoint& cp = p->index->checkpoints.at(c);
        QCOMPARE(cp.state.line, int(c) * ProgramIndex::kCheckpointLines);
        // The checkpoint's offset is where its next line starts.
        QCOMPARE(text.left(cp.offset).count('\n'), qsizetype(cp.state.line));
    }
    QCOMPARE(p->index->bytes, text.size());
}

void TestProgramReader::at_anyOrder_theBlocksTheParserGaveOut()
{
    QByteArray text = longProgram(12000);
    text.replace("M2\n%\n", "O7 repeat [2]\nG91 G0 X1\nO7 endrepeat\nM2\n%\n");
    std::optional<Program> p;
    const QList<ProgramBlock> given = streamedBlocks(text, &p);
    QVERIFY(p);
    QCOMPARE(p->blockCount, int(given.size()));
    ProgramReader reader(*p);
    QRandomGenerator random(29);
    for (int round = 0; round < 300; ++round) {
        const int i = int(random.bounded(qint64(given.size())));
        const ProgramBlock* b = reader.at(i);
        QVERIFY2(b, qPrintable(reader.error()));
        ProgramBlock expected = given.at(i);
        if (expected.kind == BlockKind::RepeatStart)
            expected.partner = p->index->partner(i); // known once its endrepeat was read
        QCOMPARE(*b, expected);
    }
    QVERIFY(!reader.at(p->blockCount));
    QVERIFY(reader.error().isEmpty());
    const int start = p->blockCount - 4;
    QCOMPARE(reader.partner(start), start + 2);
    QCOMPARE(reader.at(start + 2)->partner, start);
}

void TestProgramReader::at_blockDeleteEitherWay_readBackAsTheParserRead_data()
{
    QTest::addColumn<bool>("blockDelete");
    QTest::newRow("on: the slash lines skipped") << true;
    QTest::newRow("off: the slash lines run") << false;
}

// Block delete (issue 50 item 6) decides which lines are blocks: every reading again from a
// checkpoint (the run's, a repeat's) skips what the first reading skipped, whatever the
// reader's own default, and the check's one pass reads as the parser does.
void TestProgramReader::at_blockDeleteEitherWay_readBackAsTheParserRead()
{
    QFETCH(bool, blockDelete);
    const int lines = 3 * ProgramIndex::kCheckpointLines;
    QByteArray text = "G21 G90 G0 X0 Y0 Z5\n";
    for (int line = 2; line <= lines; ++line)
        text += line % 10 == 0 ? QByteArray("/G91 G0 Z0.1\n")
                               : "G90 G1 X" + QByteArray::number(line % 50) + " F600\n";
    QList<ProgramBlock> given;
    ProgramParser parser(kReaderAxes);
    parser.setBlockDelete(blockDelete);
    parser.setSink([&given](ProgramBlock&& b) { given << b; });
    parser.feed(text);
    std::optional<Program> p = parser.finish(nullptr);
    QVERIFY(p);
    p->source = ProgramSource::bytes(text);
    const int slashes = lines / 10;
    QCOMPARE(p->blockCount, blockDelete ? lines - slashes : lines);
    QCOMPARE(int(given.size()), p->blockCount);
    ProgramReader reader(*p);
    for (int i = p->blockCount - 1; i >= 0; --i) { // backwards: each checkpoint read again
        const ProgramBlock* b = reader.at(i);
        QVERIFY2(b, qPrintable(reader.error()));
        QCOMPARE(*b, given.at(i));
    }
    ProgramReader pass(ProgramSource::bytes(text), kReaderAxes, {}, blockDelete);
    const std::optional<Program> again = pass.finish(nullptr);
    QVERIFY(again);
    QCOMPARE(again->blockCount, p->blockCount);
    QCOMPARE(again->index->blockDelete, blockDelete);
    QCOMPARE(again->notes.size(), qsizetype(blockDelete ? 1 : 0)); // "block delete is on: …"
}

void TestProgramReader::at_fileChangedSinceRead_refusedWithReason_data()
{
    QTest::addColumn<QString>("change");
    QTest::addColumn<bool>("atOpen"); // noticed when the reader opens the file
    QTest::newRow("one digit, same length") << "digit" << false;
    QTest::newRow("cut short") << "truncate" << true;
    QTest::newRow("a line added") << "append" << true;
    QTest::newRow("file removed") << "remove" << true;
}

void TestProgramReader::at_fileChangedSinceRead_refusedWithReason()
{
    QFETCH(QString, change);
    QFETCH(bool, atOpen);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("long.ngc"));
    const QByteArray text = longProgram(9000);
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
    }
    std::optional<Program> p;
    const QList<ProgramBlock> given = streamedBlocks(text, &p);
    QVERIFY(p);
    p->source = ProgramSource::file(path);
    QCOMPARE(ProgramReader::readAll(*p), given); // unchanged: read back from the file
    // Line 6001's first digit becomes another: the same length, the same words.
    const qsizetype at = text.indexOf("G1 X", p->index->checkpoints.at(2).offset + 200) + 4;
    {
        QFile f(path);
        if (change == QLatin1String("remove")) {
            QVERIFY(f.remove());
        } else if (change == QLatin1String("append")) {
            QVERIFY(f.open(QIODevice::Append));
            f.write("G0 X1\n");
        } else {
            QVERIFY(f.open(QIODevice::ReadWrite));
            if (change == QLatin1String("truncate")) {
                QVERIFY(f.resize(text.size() - 10));
            } else {
                f.seek(at);
                f.write(text.at(at) == '9' ? "8" : "9");
            }
        }
    }
    ProgramReader reader(*p);
    QCOMPARE(reader.error().isEmpty(), !atOpen);
    // The blocks of unchanged lines still read; the changed lines are refused with the reason.
    const int before = p->index->checkpoints.at(1).state.blocks;
    if (!atOpen)
        QVERIFY2(reader.at(before), qPrintable(reader.error()));
    const int changed = p->index->checkpoints.at(2).state.blocks + 1;
    QVERIFY(!reader.at(changed));
    QVERIFY2(reader.error().contains(QLatin1String("changed since it was checked")) ||
                 reader.error().contains(QLatin1String("cannot read")),
             qPrintable(reader.error()));
    // A check of the changed program says why, and gives no program to run.
    const ProgramCheckResult result = ProgramCheck::check(*p, longMill());
    QVERIFY(!result.ok());
    QVERIFY(!result.program);
}

void TestProgramReader::firstBlockAtLine_andEnclosingRepeat_bothModes_data()
{
    QTest::addColumn<bool>("onePass");
    QTest::newRow("over a Program") << false;
    QTest::newRow("one pass") << true;
}

void TestProgramReader::firstBlockAtLine_andEnclosingRepeat_bothModes()
{
    QFETCH(bool, onePass);
    // Lines 1..5000 plain; a repeat over lines 5001..9003; one more line after it.
    QByteArray text;
    for (int i = 1; i <= 5000; ++i)
        text += i % 2 ? "G0 X1\n" : "\n"; // blocks on odd lines only
    text += "O1 repeat [2]\n";            // line 5001
    for (int i = 5002; i <= 9002; ++i)
        text += "G91 G0 X0.01\n";
    text += "O1 endrepeat\nG90 G0 X0\n"; // lines 9003, 9004
    std::optional<Program> p;
    streamedBlocks(text, &p);
    QVERIFY(p);
    std::unique_ptr<ProgramReader> reader =
        onePass ? std::make_unique<ProgramReader>(ProgramSource::bytes(text), kReaderAxes)
                : std::make_unique<ProgramReader>(*p);
    QCOMPARE(reader->firstBlockAtLine(1), 0);
    QCOMPARE(reader->firstBlockAtLine(2), 1); // line 3
    QCOMPARE(reader->at(1)->line, 3);
    const int repeat = reader->firstBlockAtLine(5001);
    QCOMPARE(repeat, 2500);
    QCOMPARE(reader->enclosingRepeat(repeat), -1);
    const int inside = reader->firstBlockAtLine(8000);
    QCOMPARE(reader->at(inside)->line, 8000);
    QCOMPARE(reader->enclosingRepeat(inside), repeat);
    const int after = reader->firstBlockAtLine(9004);
    QCOMPARE(reader->enclosingRepeat(after), -1);
    QCOMPARE(reader->firstBlockAtLine(9005), -1);
    QCOMPARE(reader->lastBlockLine(), 9004);
    QVERIFY(reader->error().isEmpty());
}

void TestProgramReader::check_onePass_sameAsParsedProgram_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("fromLine");
    // A repeat whose body (6000 blocks) is longer than the one pass keeps: its next passes are
    // read back from the index.
    QByteArray body;
    for (int i = 0; i < 6000; ++i)
        body += "G91 G1 X0.01 F600\n";
    const QByteArray repeat = "G28\nO1 repeat [3]\n" + body + "G90 G0 X0\nO1 endrepeat\nM2\n";
    QTest::newRow("long repeat") << repeat << 1;
    QTest::newRow("long repeat, from its end") << repeat << 6004;
    QTest::newRow("from inside the repeat") << repeat << 3000;
    // Errors far into the program, once per word however often a repeat runs it.
    QByteArray errors = repeat;
    errors.replace("G90 G0 X0\n", "G90 G0 X5000\n");
    QTest::newRow("errors in a long repeat") << errors << 1;
    QTest::newRow("long program") << longProgram(30000) << 1;
    QTest::newRow("long program from line 20000") << longProgram(30000) << 20000;
}

void TestProgramReader::check_onePass_sameAsParsedProgram()
{
    QFETCH(QByteArray, text);
    QFETCH(int, fromLine);
    const MachineFacts facts = longMill();
    std::optional<Program> p;
    streamedBlocks(text, &p);
    QVERIFY(p);
    const ProgramCheckResult parsed = ProgramCheck::check(*p, facts, fromLine);
    const ProgramCheckResult onePass =
        ProgramCheck::check(ProgramSource::bytes(text), kReaderAxes, facts, fromLine);
    QCOMPARE(texts(onePass.errors), texts(parsed.errors));
    QCOMPARE(onePass.ok(), parsed.ok());
    QCOMPARE(onePass.program.has_value(), parsed.ok());
    QCOMPARE(onePass.preview.blocksRun, parsed.preview.blocksRun);
    QCOMPARE(onePass.preview.estimatedSeconds, parsed.preview.estimatedSeconds);
    QCOMPARE(onePass.preview.path.size(), parsed.preview.path.size());
    QCOMPARE(onePass.preview.lines, p->lines);
    if (onePass.program)
        QCOMPARE(onePass.program->blockCount, p->blockCount);
}

void TestProgramReader::check_progressCancels_nothingKnown()
{
    const QByteArray text = longProgram(40000);
    int calls = 0;
    qint64 last = -1;
    const ProgramCheckResult result = ProgramCheck::check(
        ProgramSource::bytes(text), kReaderAxes, longMill(), 1, [&](qint64 done, qint64 total) {
            // Progress grows and never passes the length.
            [&] {
                QVERIFY(done >= last);
                QVERIFY(done <= total);
                QCOMPARE(total, text.size());
            }();
            last = done;
            return ++calls < 3;
        });
    QCOMPARE(calls, 3);
    QVERIFY(result.cancelled);
    QVERIFY(!result.ok());
    QVERIFY(!result.program);
    QVERIFY(last < text.size()); // it stopped before the end
}

void TestProgramReader::check_onePassParseError_parserErrorsOnly()
{
    // A parse error far into the file: the parser's errors, not the walk's (the soft limit of
    // line 2 would be one).
    QByteArray text = longProgram(10000);
    text.replace("%\nG21", "%\nG0 X5000\nG21");
    text.replace("M2\n", "G1 X1 Q5\nM2\n");
    const ProgramCheckResult result =
        ProgramCheck::check(ProgramSource::bytes(text), kReaderAxes, longMill());
    QCOMPARE(result.errors.size(), 1);
    QCOMPARE(result.errors.first().line, 10000);
    QVERIFY(!result.program);
}

STEPDECK_TEST_GUILESS_MAIN(TestProgramReader)
#include "tst_programreader.moc"
