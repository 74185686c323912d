// The Program page's widgets on their own (issue 20): the editor marks errors at their lines
// with their messages and the running line, and is read-only while running; the files open,
// save and remember programs and refuse what they cannot read; the estimated times are marked
// as estimates (the path view: tst_programpathview).
#include "TestMain.h"
#include "TestSupport.h"
#include "program/ProgramBackgroundCheck.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramFiles.h"
#include "program/ProgramProgress.h"
#include "program/ProgramPromptBanner.h"
#include "program/ProgramTimes.h"
#include "protocols/Registry.h"
#include <QApplication>
#include <QCheckBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QThreadPool>
#include <QtTest>
#include <tuple>

using namespace stepdeck;
using namespace stepdeck::ui;

class TestProgramWidgets : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void editor_errors_markedAtTheirLinesWithMessages();
    void editor_errorsCleared_noMarks();
    void editor_running_readOnlyAndLineHighlighted();
    void files_saveThenLoad_sameTextAndRecent();
    void files_missingFile_refusedEditorKept();
    void times_data();
    void times();
    void controls_states_onlyUsefulButtonsEnabled_data();
    void controls_states_onlyUsefulButtonsEnabled();
    void controls_optionalStops_onByDefaultRememberedBesideRunFrom();
    void controls_blockDelete_onByDefaultRememberedOffWhileRunning();
    void banner_prompt_keepsItsHeight();
    void backgroundCheck_twoRequests_onlyTheNewestReports();
    void progress_blocksOfARepeat_timeLeftFollowsThePath();
    void timeLeft_override50_feedTimeDoubles();
    void timeLeft_longLine_countsItsSecondsNotOneStep();
    void timeLeft_thinnedPath_followsTheKeptPointsTimes();
    void controls_timeLeft_followsTheOverrideBoxAtOnce();
};

void TestProgramWidgets::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUiTest-tst_programwidgets"));
    QSettings().clear();
}

void TestProgramWidgets::editor_errors_markedAtTheirLinesWithMessages()
{
    ProgramEditor editor;
    editor.setPlainText(QStringLiteral("G0 X1\nT2\nG0 Y1\nG7\n"));
    editor.setErrors({{2, 1, QStringLiteral("T2 is not a word")}, {4, 1, QStringLiteral("G7?")}});
    QCOMPARE(editor.errorLines(), (QList<int>{2, 4}));
    QCOMPARE(editor.toolTipForLine(2), QStringLiteral("2:1: T2 is not a word"));
    QVERIFY(editor.toolTipForLine(1).isEmpty());
    // The marks are on the text's lines too: one tinted line per error.
    const QList<QTextEdit::ExtraSelection> marks = editor.extraSelections();
    QCOMPARE(marks.size(), 2);
    QCOMPARE(marks.at(0).cursor.blockNumber(), 1);
    QCOMPARE(marks.at(1).cursor.blockNumber(), 3);
    // The line under the pointer is found where it is drawn.
    editor.resize(400, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    const QTextBlock second = editor.document()->findBlockByNumber(1);
    const QRect r = editor.cursorRect(QTextCursor(second));
    QCOMPARE(editor.lineAt(r.center()), 2);
}

void TestProgramWidgets::editor_errorsCleared_noMarks()
{
    ProgramEditor editor;
    editor.setPlainText(QStringLiteral("T2\n"));
    editor.setErrors({{1, 1, QStringLiteral("T2 is not a word")}});
    editor.setErrors({});
    QVERIFY(editor.errorLines().isEmpty());
    QVERIFY(editor.extraSelections().isEmpty());
}

void TestProgramWidgets::editor_running_readOnlyAndLineHighlighted()
{
    ProgramEditor editor;
    editor.setPlainText(QStringLiteral("G91\nG0 X1\nG0 X1\n"));
    editor.setRunning(true);
    QVERIFY(editor.isReadOnly());
    editor.setRunningLine(3);
    QCOMPARE(editor.runningLine(), 3);
    QCOMPARE(editor.extraSelections().size(), 1);
    QCOMPARE(editor.extraSelections().first().cursor.blockNumber(), 2);
    // Typing does nothing while running.
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    QTest::keyClicks(editor.viewport(), QStringLiteral("M2"));
    QCOMPARE(editor.toPlainText(), QStringLiteral("G91\nG0 X1\nG0 X1\n"));
    editor.setRunning(false);
    QVERIFY(!editor.isReadOnly());
    QCOMPARE(editor.runningLine(), 0);
    QVERIFY(editor.extraSelections().isEmpty());
}

void TestProgramWidgets::files_saveThenLoad_sameTextAndRecent()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("part.ngc"));
    QPlainTextEdit editor;
    ProgramFiles files(&editor);
    editor.insertPlainText(QStringLiteral("G21 G90\n(\u00e4 comment)\nM30\n")); // typed
    QVERIFY(files.isModified());
    QCOMPARE(files.fileText(), QStringLiteral("Untitled *"));
    QVERIFY(files.saveTo(path));
    QVERIFY(!files.isModified());
    QCOMPARE(files.fileText(), QStringLiteral("part.ngc"));
    editor.setPlainText(QStringLiteral("other"));
    QSignalSpy loaded(&files, &ProgramFiles::loaded);
    QVERIFY(files.load(path));
    QCOMPARE(loaded.size(), 1);
    QCOMPARE(editor.toPlainText(), QStringLiteral("G21 G90\n(\u00e4 comment)\nM30\n"));
    QCOMPARE(recentprograms::list().value(0), QFileInfo(path).absoluteFilePath());
}

void TestProgramWidgets::files_missingFile_refusedEditorKept()
{
    QPlainTextEdit editor;
    ProgramFiles files(&editor);
    editor.setPlainText(QStringLiteral("G0 X1"));
    QSignalSpy message(&files, &ProgramFiles::message);
    QVERIFY(!files.load(QStringLiteral("/nonexistent/part.ngc")));
    QCOMPARE(message.size(), 1);
    QVERIFY(message.first().first().toString().contains(QStringLiteral("part.ngc")));
    QCOMPARE(editor.toPlainText(), QStringLiteral("G0 X1"));
}

void TestProgramWidgets::times_data()
{
    QTest::addColumn<double>("seconds");
    QTest::addColumn<QString>("duration");
    QTest::addRow("seconds") << 12.4 << QStringLiteral("\u2248 12 s (estimated)");
    QTest::addRow("minutes") << 80.0 << QStringLiteral("\u2248 1 min 20 s (estimated)");
    QTest::addRow("hours") << 7500.0 << QStringLiteral("\u2248 2 h 5 min (estimated)");
    QTest::addRow("negative") << -3.0 << QStringLiteral("\u2248 0 s (estimated)");
}

void TestProgramWidgets::times()
{
    QFETCH(double, seconds);
    QFETCH(QString, duration);
    QCOMPARE(ProgramTimes::estimatedDuration(seconds), duration);
}

void TestProgramWidgets::controls_states_onlyUsefulButtonsEnabled_data()
{
    using program::RunState;
    QTest::addColumn<int>("state");
    QTest::addColumn<bool>("pausePending");
    QTest::addColumn<QString>("enabled"); // run pause resume step abort runFrom
    QTest::addRow("idle") << int(RunState::Idle) << false << QStringLiteral("R..S.F");
    QTest::addRow("running") << int(RunState::Running) << false << QStringLiteral(".P..A.");
    QTest::addRow("pause pending") << int(RunState::Running) << true << QStringLiteral("....A.");
    QTest::addRow("paused") << int(RunState::Paused) << false << QStringLiteral("..USA.");
    QTest::addRow("stopping") << int(RunState::Stopping) << false << QStringLiteral("......");
    QTest::addRow("aborted") << int(RunState::Aborted) << false << QStringLiteral("R..S.F");
}

void TestProgramWidgets::controls_states_onlyUsefulButtonsEnabled()
{
    QFETCH(int, state);
    QFETCH(bool, pausePending);
    QFETCH(QString, enabled);
    ProgramControls controls;
    controls.setState(program::RunState(state), pausePending, true);
    QString shown;
    const QList<QPair<QPushButton*, QChar>> buttons{
        {controls.runButton(), QLatin1Char('R')},    {controls.pauseButton(), QLatin1Char('P')},
        {controls.resumeButton(), QLatin1Char('U')}, {controls.stepButton(), QLatin1Char('S')},
        {controls.abortButton(), QLatin1Char('A')},  {controls.runFromButton(), QLatin1Char('F')}};
    for (const auto& [button, letter] : buttons)
        shown += button->isEnabled() ? letter : QLatin1Char('.');
    QCOMPARE(shown, enabled);
}

// Issue 29: the optional-stop switch (M1) is on when nothing was stored, says when it is
// switched, is remembered for the next window, and sits in the row of "Run from line" (the
// controls take two rows since issue 31, so that the page fits the Run workspace).
void TestProgramWidgets::controls_optionalStops_onByDefaultRememberedBesideRunFrom()
{
    QSettings().remove(QStringLiteral("programs/optionalStops"));
    {
        ProgramControls controls;
        QVERIFY(controls.optionalStops());
        QVERIFY(controls.optionalStopsBox()->isChecked());
        QVERIFY(controls.optionalStopsBox()->text().contains(QStringLiteral("M1")));
        controls.resize(controls.sizeHint());
        controls.show();
        QVERIFY(QTest::qWaitForWindowExposed(&controls));
        // The switch beside "Run from line", no taller than it is.
        const QRect box = controls.optionalStopsBox()->geometry();
        const QRect run = controls.runFromButton()->geometry();
        QVERIFY2(box.top() >= run.top() - 2 && box.bottom() <= run.bottom() + 2,
                 qPrintable(QStringLiteral("box %1..%2, run %3..%4")
                                .arg(box.top())
                                .arg(box.bottom())
                                .arg(run.top())
                                .arg(run.bottom())));
        // The row is as high with the switch as without it.
        const int withSwitch = controls.sizeHint().height();
        controls.optionalStopsBox()->hide();
        QCOMPARE(controls.sizeHint().height(), withSwitch);
        controls.optionalStopsBox()->show();
        QSignalSpy changed(&controls, &ProgramControls::optionalStopsChanged);
        controls.optionalStopsBox()->click();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.at(0).at(0).toBool(), false);
        QVERIFY(!controls.optionalStops());
    }
    {
        ProgramControls again; // the next window: as the operator left it
        QVERIFY(!again.optionalStops());
        again.optionalStopsBox()->click();
    }
    QVERIFY(ProgramControls().optionalStops());
}

// Issue 50 item 6: the block delete switch is on when nothing was stored (as LinuxCNC starts),
// says when it is switched, is remembered, and cannot change while a program runs (the check
// read it).
void TestProgramWidgets::controls_blockDelete_onByDefaultRememberedOffWhileRunning()
{
    QSettings().remove(QStringLiteral("programs/blockDelete"));
    {
        ProgramControls controls;
        QVERIFY(controls.blockDelete());
        QVERIFY(controls.blockDeleteBox()->text().contains(QStringLiteral("/")));
        controls.setState(program::RunState::Running, false, true);
        QVERIFY(!controls.blockDeleteBox()->isEnabled());
        controls.setState(program::RunState::Finished, false, true);
        QVERIFY(controls.blockDeleteBox()->isEnabled());
        QSignalSpy changed(&controls, &ProgramControls::blockDeleteChanged);
        controls.blockDeleteBox()->click();
        QCOMPARE(changed.size(), 1);
        QCOMPARE(changed.at(0).at(0).toBool(), false);
        QVERIFY(!controls.blockDelete());
    }
    QVERIFY(!ProgramControls().blockDelete()); // the next window: as the operator left it
    QSettings().remove(QStringLiteral("programs/blockDelete"));
}

void TestProgramWidgets::banner_prompt_keepsItsHeight()
{
    ProgramPromptBanner banner;
    banner.resize(500, banner.sizeHint().height());
    banner.show();
    QVERIFY(QTest::qWaitForWindowExposed(&banner));
    const int before = banner.sizeHint().height();
    banner.showPrompt(7, QStringLiteral("Remove the parts, then Resume. ") +
                             QString(200, QLatin1Char('x')));
    QCOMPARE(banner.sizeHint().height(), before);
    QVERIFY(banner.text().contains(QStringLiteral("Remove the parts")));
    QVERIFY(banner.resumeButton()->isVisible());
    QSignalSpy resume(&banner, &ProgramPromptBanner::resumeRequested);
    banner.resumeButton()->click();
    QCOMPARE(resume.size(), 1);
    banner.clearPrompt();
    QVERIFY(!banner.resumeButton()->isVisible());
    QCOMPARE(banner.sizeHint().height(), before);
}

void TestProgramWidgets::backgroundCheck_twoRequests_onlyTheNewestReports()
{
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    program::MachineFacts facts;
    facts.description = machine::MachineDescription::singleController(*elab, QStringLiteral("sim"));
    facts.capabilities.insert(elab->id, elab->capabilities);
    facts.schemas.insert(elab->id, elab->schema);
    const QStringList axes{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    ProgramBackgroundCheck checker;
    QSignalSpy checked(&checker, &ProgramBackgroundCheck::checked);
    QByteArray big;
    for (int i = 0; i < 20000; ++i)
        big += "G91 G0 X1\nT2\n"; // errors (at most kMaxErrors of them)
    checker.start(big, axes, facts);
    checker.start("G91\nG0 X1\nM2\n", axes, facts);
    QVERIFY(checker.isChecking());
    QTRY_VERIFY(!checker.isChecking());
    // The older request ends too, and reports nothing.
    QThreadPool::globalInstance()->waitForDone();
    QCoreApplication::processEvents();
    QCOMPARE(checked.size(), 1);
    const auto result = checked.first().first().value<program::ProgramCheckResult>();
    QVERIFY(result.ok());
    QCOMPARE(result.preview.lines, 3);
    // The same answer as checking on the spot.
    QCOMPARE(
        ProgramBackgroundCheck::run(stepdeck::program::ProgramSource::bytes("G0 Q1\n"), axes, facts)
            .errors.size(),
        1);
}

void TestProgramWidgets::progress_blocksOfARepeat_timeLeftFollowsThePath()
{
    // O1 repeat [2] around line 2 (G0, 1 s), line 3 (M64: no point), line 4 (G4 P2); each
    // point with the blocks finished there (PreviewPoint::blocksDone).
    program::ProgramPreview preview;
    preview.estimatedSeconds = 6;
    for (const auto& [line, seconds, blocks] : QList<std::tuple<int, double, qint64>>{
             {0, 0, 0}, {2, 1, 1}, {4, 3, 3}, {2, 4, 4}, {4, 6, 6}})
        preview.path << program::PreviewPoint{line, seconds, {}, false, 0, blocks};
    ProgramProgress progress;
    progress.reset(preview);
    QCOMPARE(progress.secondsLeft().value_or(-1), 6.0);
    progress.blockFinished(2);
    QCOMPARE(progress.secondsLeft().value_or(-1), 5.0);
    progress.blockFinished(3); // no point of its own: the time stays
    QCOMPARE(progress.secondsLeft().value_or(-1), 5.0);
    progress.blockFinished(4);
    QCOMPARE(progress.secondsLeft().value_or(-1), 3.0);
    progress.blockFinished(2); // the second time round
    QCOMPARE(progress.secondsLeft().value_or(-1), 2.0);
    progress.blockFinished(3);
    progress.blockFinished(4);
    QCOMPARE(progress.secondsLeft().value_or(-1), 0.0);
    // A thinned path (issue 47, item 11: by time, not by the share of blocks): the points of
    // blocks 1 and 4 left out, the blocks between two kept points share their time.
    preview.pathDecimated = true;
    preview.blocksRun = 6;
    preview.path = {program::PreviewPoint{0, 0, {}, false, 0, 0},
                    program::PreviewPoint{4, 3, {}, false, 0, 3},
                    program::PreviewPoint{4, 6, {}, false, 0, 6}};
    progress.reset(preview);
    QCOMPARE(progress.secondsLeft().value_or(-1), 6.0);
    progress.blockFinished(2);
    progress.blockFinished(3);
    QCOMPARE(progress.secondsLeft().value_or(-1), 4.0); // 2 of the 3 blocks to 3 s
    for (int i = 0; i < 4; ++i)
        progress.blockFinished(4);
    QCOMPARE(progress.secondsLeft().value_or(-1), 0.0);
    preview.estimatedSeconds = 0; // no estimate: nothing to tell
    progress.reset(preview);
    QVERIFY(!progress.secondsLeft());
}

namespace {
// A G1 of 10 s (line 1), a G0 of 2 s (line 2), a G4 P3 (line 3), a G1 of 10 s (line 4).
program::ProgramPreview feedsRapidAndDwell()
{
    program::ProgramPreview preview;
    preview.lines = 4;
    preview.blocksRun = 4;
    preview.estimatedSeconds = 25;
    preview.path = {program::PreviewPoint{0, 0, {}, false, 0, 0},
                    program::PreviewPoint{1, 10, {}, false, 10, 1},
                    program::PreviewPoint{2, 12, {}, true, 10, 2},
                    program::PreviewPoint{3, 15, {}, false, 10, 3},
                    program::PreviewPoint{4, 25, {}, false, 20, 4}};
    return preview;
}
} // namespace

// Issue 47, item 11: at a feed override of 50 % the feed moves take twice their time, at
// 200 % half; the rapid and the dwell keep theirs.
void TestProgramWidgets::timeLeft_override50_feedTimeDoubles()
{
    ProgramProgress progress;
    progress.reset(feedsRapidAndDwell());
    QCOMPARE(progress.feedOverride(), 100.0);
    QCOMPARE(progress.secondsLeft().value_or(-1), 25.0);
    QCOMPARE(progress.timeLeft()->feedSeconds, 20.0);
    QCOMPARE(progress.timeLeft()->otherSeconds, 5.0);
    progress.setFeedOverride(50);
    QCOMPARE(progress.secondsLeft().value_or(-1), 2 * 20.0 + 5);
    progress.blockFinished(1);
    QCOMPARE(progress.secondsLeft().value_or(-1), 2 * 10.0 + 5);
    progress.setFeedOverride(100);
    QCOMPARE(progress.secondsLeft().value_or(-1), 15.0);
    progress.blockFinished(2); // the rapid
    progress.setFeedOverride(50);
    QCOMPARE(progress.secondsLeft().value_or(-1), 2 * 10.0 + 3);
    progress.setFeedOverride(200);
    QCOMPARE(progress.secondsLeft().value_or(-1), 10.0 / 2 + 3);
    // Where the run stands on the preview's clock does not depend on the override.
    QCOMPARE(progress.secondsDone(), 12.0);
    progress.blockFinished(3);
    progress.blockFinished(4);
    QCOMPARE(progress.secondsLeft().value_or(-1), 0.0);
    // A new run keeps the override (the runner's); the estimate starts again.
    progress.reset(feedsRapidAndDwell());
    QCOMPARE(progress.secondsLeft().value_or(-1), 20.0 / 2 + 5);
}

// A block of 10 s is 10 s of the time left, not a quarter of it (one block of four).
void TestProgramWidgets::timeLeft_longLine_countsItsSecondsNotOneStep()
{
    program::ProgramPreview preview = feedsRapidAndDwell();
    preview.path[1].seconds = 20; // line 1 takes 20 s, the rest as before
    preview.path[1].feedSeconds = 20;
    for (qsizetype i = 2; i < preview.path.size(); ++i) {
        preview.path[i].seconds += 10;
        preview.path[i].feedSeconds += 10;
    }
    preview.estimatedSeconds = 35;
    ProgramProgress progress;
    progress.reset(preview);
    progress.blockFinished(1);
    QCOMPARE(progress.secondsLeft().value_or(-1), 15.0);
    progress.blockFinished(2);
    QCOMPARE(progress.secondsLeft().value_or(-1), 13.0);
}

// A thinned path: between two kept points the blocks share the time by their count; a kept
// point's block is where its seconds say.
void TestProgramWidgets::timeLeft_thinnedPath_followsTheKeptPointsTimes()
{
    program::ProgramPreview preview;
    preview.estimatedSeconds = 38;
    preview.blocksRun = 9;
    preview.pathDecimated = true;
    // Block 1 a G1 of 30 s; blocks 2..5 and 6..9 of 1 s each, their points thinned out but
    // for the last of each.
    preview.path = {program::PreviewPoint{0, 0, {}, false, 0, 0},
                    program::PreviewPoint{1, 30, {}, false, 30, 1},
                    program::PreviewPoint{5, 34, {}, false, 34, 5},
                    program::PreviewPoint{9, 38, {}, false, 38, 9}};
    ProgramProgress progress;
    progress.reset(preview);
    progress.blockFinished(1);
    QCOMPARE(progress.secondsLeft().value_or(-1), 8.0); // not 38 x 8/9 blocks
    progress.blockFinished(2);
    progress.blockFinished(3);
    QCOMPARE(progress.secondsLeft().value_or(-1), 6.0);
    progress.setFeedOverride(50);
    QCOMPARE(progress.secondsLeft().value_or(-1), 12.0);
}

// The Program page's time left follows the feed override box as soon as it changes, at the
// feed moves' share; without a run it says nothing.
void TestProgramWidgets::controls_timeLeft_followsTheOverrideBoxAtOnce()
{
    ProgramControls controls;
    QCOMPARE(controls.feedOverride(), 100);
    controls.setProgress(3, 10, ProgramTimeLeft{60, 10});
    QCOMPARE(controls.timeLeftText(), ProgramTimes::estimatedLeft(70));
    controls.feedOverrideBox()->setValue(50);
    QCOMPARE(controls.timeLeftText(), ProgramTimes::estimatedLeft(130));
    controls.feedOverrideBox()->setValue(200);
    QCOMPARE(controls.timeLeftText(), ProgramTimes::estimatedLeft(40));
    controls.setProgress(4, 10, std::nullopt);
    QCOMPARE(controls.timeLeftText(), QStringLiteral("time left unknown"));
    controls.feedOverrideBox()->setValue(100);
    QCOMPARE(controls.timeLeftText(), QStringLiteral("time left unknown"));
    controls.clearProgress();
    controls.feedOverrideBox()->setValue(50);
    QVERIFY(controls.timeLeftText().isEmpty());
    QCOMPARE(controls.progressText(), QStringLiteral("not running"));
}

STEPDECK_TEST_MAIN(TestProgramWidgets)
#include "tst_programwidgets.moc"
