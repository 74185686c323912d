// The Program page with a program too large to edit (issue 29, "streamed, any length"), on the
// machine of MachineWindowRig (an E-LAB X/Y/Z table at 400 steps/mm, a Nanotec rotary axis A,
// simulated on pseudo-terminals): the file is shown as a read-only excerpt that can never be
// saved over it, checked from the file with a progress bar that cancels, and run from the file
// (the moves asserted at the simulated board); a file changed on disk after its check is
// refused before anything reaches the board.
#include "../machine/MachineWindowRig.h"
#include "TestMain.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramFiles.h"
#include "program/ProgramPage.h"
#include "safety/SafetyBar.h"
#include <QProgressBar>
#include <QPushButton>
#include <QThreadPool>

using namespace stepdeck;
using namespace stepdeck::test;
using program::RunState;

class TestProgramPageLarge : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void largeFile_excerptReadOnly_runFromTheFileAtTheBoard();
    void largeFile_changedAfterCheck_refusedNothingSent();
    void check_long_progressShownCancelStopsIt();
    void run_stoppedWhileCheckedBeforeIt_neverStartsNothingSent_data();
    void run_stoppedWhileCheckedBeforeIt_neverStartsNothingSent();

private:
    ui::MainWindow* window() const { return m_rig.window(); }
    ui::ProgramPage* page() const { return window()->programPage(); }
    program::ProgramRunner* runner() const { return page()->runner(); }
    // A run asked for is first checked off the GUI thread (ProgramStarter): until then the
    // runner still has the state of the run before.
    bool runState(RunState state) const
    {
        return runner() && !page()->isStarting() && runner()->state() == state;
    }

    // Two moves, then comment lines up to past the editor's limit, then one more move: the
    // lines to run sit at both ends of a file the editor does not hold.
    QString writeLargeProgram()
    {
        QByteArray text = "G91\nG0 X0.5\n";
        const QByteArray padding = "(finishing pass, a comment line that pads the file)\n";
        while (text.size() <= ui::ProgramFiles::kMaxEditBytes)
            text += padding;
        text += "G0 Y0.25\nM2\n";
        m_lines = int(text.count('\n'));
        const QString path = m_rig.dir->filePath(QStringLiteral("large.ngc"));
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
            return {};
        return path;
    }

    MachineWindowRig m_rig;
    int m_lines = 0;
};

void TestProgramPageLarge::largeFile_excerptReadOnly_runFromTheFileAtTheBoard()
{
    QVERIFY(m_rig.openAndConnect());
    window()->raisePage(page());
    const QString path = writeLargeProgram();
    QVERIFY(!path.isEmpty());
    QVERIFY(page()->files()->load(path));
    // The excerpt: its first lines, read-only, and nothing that could save it over the file.
    QCOMPARE(page()->editor()->blockCount(), ui::ProgramFiles::kExcerptLines);
    QVERIFY(page()->editor()->isReadOnly());
    QVERIFY(!page()->files()->saveButton()->isEnabled());
    QVERIFY(!page()->files()->saveTo(path + QStringLiteral(".copy")));
    QVERIFY(!QFile::exists(path + QStringLiteral(".copy")));
    QVERIFY2(page()->messageText().contains(QStringLiteral("too large to edit")),
             qPrintable(page()->messageText()));
    // Checked from the file: Run comes on once the whole file is checked.
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 60000);
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 60000);
    // At the board: the first move and the last, 0.5 mm and 0.25 mm at 400 steps/mm.
    QCOMPARE(m_rig.elab->position(Axis::X), 200);
    QCOMPARE(m_rig.elab->position(Axis::Y), 100);
    QVERIFY(m_rig.elab->still());
    QVERIFY(page()->editor()->isReadOnly()); // still an excerpt after the run
    // A small program opened next: editable, Save back, and nothing said of the large one or
    // of its run any more.
    const QString small = m_rig.dir->filePath(QStringLiteral("small.ngc"));
    {
        QFile f(small);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("G91\nG0 X0.5\n");
    }
    QVERIFY(page()->files()->load(small));
    QVERIFY(!page()->editor()->isReadOnly());
    QVERIFY(page()->files()->saveButton()->isEnabled());
    QVERIFY2(page()->messageText().isEmpty(), qPrintable(page()->messageText()));
}

void TestProgramPageLarge::largeFile_changedAfterCheck_refusedNothingSent()
{
    QVERIFY(m_rig.openAndConnect());
    window()->raisePage(page());
    const QString path = writeLargeProgram();
    QVERIFY(page()->files()->load(path));
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 60000);
    {
        // Changed on disk after the check: the first move becomes a longer one.
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.seek(8)); // "G91\nG0 X0.5": the "0" of 0.5
        QCOMPARE(f.write("9"), qint64(1));
    }
    page()->controls()->runButton()->click();
    QTRY_VERIFY2(page()->messageText().contains(QStringLiteral("changed since it was checked")),
                 qPrintable(page()->messageText()));
    QVERIFY(!runState(RunState::Running));
    // Nothing reached the board.
    QCOMPARE(m_rig.elab->position(Axis::X), 0);
    QCOMPARE(m_rig.elab->position(Axis::Y), 0);
}

void TestProgramPageLarge::check_long_progressShownCancelStopsIt()
{
    QVERIFY(m_rig.openAndConnect());
    window()->raisePage(page());
    page()->setCheckProgressDelay(0);
    const QString path = writeLargeProgram();
    QVERIFY(page()->files()->load(path));
    // The check runs: its progress in place of the check's line, with Cancel.
    QTRY_VERIFY(page()->isShowingCheckProgress());
    QVERIFY(page()->checkProgress()->isVisible());
    QVERIFY(page()->cancelCheckButton()->isVisible());
    page()->cancelCheckButton()->click();
    QVERIFY(!page()->isShowingCheckProgress());
    QVERIFY(!page()->isChecking());
    QVERIFY2(page()->checkText().contains(QStringLiteral("cancelled")),
             qPrintable(page()->checkText()));
    QVERIFY(!page()->controls()->runButton()->isEnabled());
    // Check checks again.
    window()->findChild<QPushButton*>(QStringLiteral("programCheckNow"))->click();
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 60000);
    QVERIFY(!page()->isShowingCheckProgress());
}

void TestProgramPageLarge::run_stoppedWhileCheckedBeforeIt_neverStartsNothingSent_data()
{
    QTest::addColumn<QString>("how");
    QTest::addColumn<QString>("reason");
    QTest::newRow("cancel") << "cancel"
                            << "the check was cancelled";
    QTest::newRow("stop") << "stop"
                          << "stopped while the program was checked before the run";
    QTest::newRow("panic") << "panic"
                           << "stopped while the program was checked before the run";
}

// Run checks the program once more against the machine as it stands, off the GUI thread (a
// file of millions of lines takes seconds): progress and Cancel show, Run is off, and STOP,
// PANIC or Cancel meanwhile mean the run never starts, also once that check would have ended.
void TestProgramPageLarge::run_stoppedWhileCheckedBeforeIt_neverStartsNothingSent()
{
    QFETCH(QString, how);
    QFETCH(QString, reason);
    QVERIFY(m_rig.openAndConnect());
    window()->raisePage(page());
    page()->setCheckProgressDelay(0);
    QVERIFY(page()->files()->load(writeLargeProgram()));
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 60000);
    page()->controls()->runButton()->click();
    QVERIFY(page()->isStarting());
    QVERIFY(!page()->controls()->runButton()->isEnabled());
    QVERIFY(page()->isShowingCheckProgress());
    QVERIFY(page()->cancelCheckButton()->isVisible());
    QVERIFY2(page()->messageText().contains(QStringLiteral("before the run")),
             qPrintable(page()->messageText()));
    if (how == QLatin1String("cancel"))
        page()->cancelCheckButton()->click();
    else if (how == QLatin1String("stop"))
        window()->safetyBar()->stopButton()->click();
    else
        window()->safetyBar()->panicButton()->click();
    QVERIFY(!page()->isStarting());
    QVERIFY(!page()->isShowingCheckProgress());
    QVERIFY2(page()->messageText().contains(reason), qPrintable(page()->messageText()));
    // The cancelled check ends at its next step; whatever it reports then starts nothing.
    QThreadPool::globalInstance()->waitForDone();
    QCoreApplication::processEvents();
    QCOMPARE(runner()->state(), RunState::Idle);
    QVERIFY(m_rig.elab->still());
    QCOMPARE(m_rig.elab->position(Axis::X), 0);
    QCOMPARE(m_rig.elab->position(Axis::Y), 0);
}

STEPDECK_TEST_MAIN(TestProgramPageLarge)
#include "tst_programpagelarge.moc"
