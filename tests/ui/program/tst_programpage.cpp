// The Program page in the main window (issue 20) on a machine of two simulated controllers
// (ProgramPageFixture): the check's errors are marked at their lines; Run sends the moves
// (asserted at the simulated device); the position is drawn in the path; Run from line confirms
// where it starts; the page fits a 1366x768 laptop; the connection's machine is the one
// programs run on; a program with errors keeps the path its check walked beside the list of
// its errors (issue 47 item 12). Holding, stopping and faults while a program runs:
// tst_programpagerun.
#include "ProgramPageFixture.h"
#include "TestMain.h"
#include "program/ProgramErrorList.h"
#include <QListWidget>
#include <QTabWidget>

using namespace stepdeck;
using namespace stepdeck::test;
using program::RunState;

class TestProgramPage : public ProgramPageFixture
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void check_errorInProgram_markedAtItsLine();
    void check_validProgram_previewWithEstimatedDuration();
    void run_validProgram_deviceReceivedTheMoves();
    void position_whileRunning_drawnInThePath();
    void runFromLine_confirmationNamesThePosition();
    void page_fitsTheLaptopScreen();
    void connection_singleController_isTheMachineProgramsRunOn();
    void connection_keepsTheControllersUnitsLimitsAndReferencing();
    void check_setupWrittenMeanwhile_checkedAgainRunEnabled();
    void check_feedAboveTheHighest_noteShownRunStaysEnabled();
    void run_afterZeroXY_programInWorkCoordinatesAtTheBoard();
    void linuxcncLanguage_errorsAtFileLines_runMovesTheDevice();
    void preview_softLimitErrors_pathShownWithTheErrors();
    void preview_parseErrors_listOnly();
    void preview_errorsComeAndGo_layoutHoldsStill();

private:
    // The table with X's soft limits 0..100 mm, connected, X, Y and Z referenced (at 0).
    bool openLimitedTable()
    {
        return m_rig.openAndConnect(
                   m_rig.machineJson(QStringLiteral("Limited table"),
                                     QStringLiteral(", \"softLimits\": [0, 100]"))) &&
               m_rig.referenceTable();
    }
    // Where a widget of the page stands in the window.
    QRect placeOf(const QWidget* w) const { return QRect(w->mapTo(window(), QPoint()), w->size()); }
};

namespace {
// Issue 47 item 12: X goes to 120 mm, beyond its soft limits 0..100 mm, on line 3 (column 4).
const QString kBeyondTheLimits = QStringLiteral("G90\nG0 X10 Y5\nG0 X120 Y5\nG0 X10 Y5\nM2\n");
const QString kWithinTheLimits = QStringLiteral("G90\nG0 X10 Y5\nG0 X90 Y5\nG0 X10 Y5\nM2\n");
const QString kDoesNotParse = QStringLiteral("G90\nG0 Q1 X10\nM2\n"); // Q is no word of G0
} // namespace

void TestProgramPage::check_errorInProgram_markedAtItsLine()
{
    QVERIFY(window()->openMachine(m_rig.writeFile(m_rig.machineJson())));
    setProgram(QStringLiteral("G91\nG0 X1\nG0 Q1 X2\nG0 Y1\n"));
    QCOMPARE(page()->editor()->errorLines(), QList<int>{3});
    QVERIFY2(page()->editor()->errorAt(3).startsWith(QStringLiteral("3:")),
             qPrintable(page()->editor()->errorAt(3)));
    QVERIFY2(page()->checkText().contains(QStringLiteral("line 3")),
             qPrintable(page()->checkText()));
    QVERIFY(!page()->controls()->runButton()->isEnabled());
    // Fixed by typing: the debounced check clears the mark by itself.
    QTextCursor c(page()->editor()->document()->findBlockByNumber(2));
    c.select(QTextCursor::LineUnderCursor);
    c.insertText(QStringLiteral("G0 X2"));
    QTRY_VERIFY(page()->editor()->errorLines().isEmpty());
}

void TestProgramPage::check_validProgram_previewWithEstimatedDuration()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable()); // X, Y, Z known: the preview follows them
    setProgram(QStringLiteral("G90\nG0 X1 Y2\nG0 Z0.5\nG91 G0 A90\nM2\n"));
    QVERIFY2(page()->editor()->errorLines().isEmpty(), qPrintable(page()->checkText()));
    const QString figures = page()->preview()->figuresText();
    QVERIFY2(figures.contains(QStringLiteral("5 line")), qPrintable(figures));
    QVERIFY2(figures.contains(QStringLiteral("(estimated)")), qPrintable(figures));
    QVERIFY(page()->preview()->pathView()->points().contains(QPointF(1, 2)));
    // Z (not X/Y) is charted over time; A's position is not known, so it is not drawn.
    const QString charted = page()->preview()->chartedAxes().join(QLatin1Char(','));
    QVERIFY2(charted.contains(QStringLiteral("Z (mm)")) && !charted.contains(QStringLiteral("A")),
             qPrintable(charted));
    // Each moved axis' extent against its soft limits.
    QTableWidget* extents = page()->preview()->extentsTable();
    QStringList rows;
    for (int r = 0; r < extents->rowCount(); ++r)
        rows << extents->item(r, 0)->text() + QLatin1Char(' ') + extents->item(r, 2)->text();
    QVERIFY2(rows.contains(QStringLiteral("Z 0.500 mm")), qPrintable(rows.join(QLatin1Char(';'))));
}

void TestProgramPage::run_validProgram_deviceReceivedTheMoves()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X0.5\nG0 Y0.25\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    // At the device: 0.5 mm and 0.25 mm at 400 steps/mm.
    QCOMPARE(m_rig.elab->position(Axis::X), 200);
    QCOMPARE(m_rig.elab->position(Axis::Y), 100);
    QVERIFY(m_rig.elab->still());
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Finished")),
             qPrintable(page()->messageText()));
    QVERIFY(!page()->editor()->isReadOnly());
}

void TestProgramPage::position_whileRunning_drawnInThePath()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    setProgram(QStringLiteral("G90\nG0 X0.5 Y0.25\nM0 (Look)\nM2\n"));
    QTRY_VERIFY2(page()->controls()->runButton()->isEnabled(), qPrintable(page()->checkText()));
    // The path as checked: from where the axes stand to the block's end.
    QVERIFY(page()->preview()->pathView()->points().contains(QPointF(0.5, 0.25)));
    QVERIFY(!page()->preview()->pathView()->current());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(page()->promptBanner()->isShowingPrompt(), 20000);
    // Where the machine stands (read back), drawn while the program holds at M0.
    const machine::MachineAxis* x = m_rig.machine()->description().axis(QStringLiteral("X"));
    QTRY_COMPARE(m_rig.machine()->axisStatus(*x).position, 0.5);
    QTRY_COMPARE(page()->preview()->pathView()->current().value_or(QPointF(-1, -1)),
                 QPointF(0.5, 0.25));
    // The running line is the path's highlighted line too (issue 29).
    QCOMPARE(page()->preview()->pathView()->runningLine(), page()->editor()->runningLine());
    QVERIFY(page()->preview()->pathView()->runningLine() > 0);
    QVERIFY2(page()->controls()->progressText() == QStringLiteral("line 3 of 4"),
             qPrintable(page()->controls()->progressText()));
    QVERIFY2(page()->controls()->timeLeftText().contains(QStringLiteral("left (estimated)")),
             qPrintable(page()->controls()->timeLeftText()));
    page()->promptBanner()->resumeButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QVERIFY(!page()->preview()->pathView()->current()); // not running: no marker
    QCOMPARE(page()->preview()->pathView()->runningLine(), 0);
}

void TestProgramPage::runFromLine_confirmationNamesThePosition()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\nG0 X0.5\nG0 Y0.25\nM2\n"));
    QTRY_VERIFY(page()->controls()->runFromButton()->isEnabled());
    const QString text = page()->runFromText(3);
    QVERIFY2(text.contains(QStringLiteral("line 3")) && text.contains(QStringLiteral("G0 Y0.25")),
             qPrintable(text));
    // Where the axes stand: X and Y are read back (not referenced yet: estimated, but known).
    QVERIFY2(text.contains(QStringLiteral("X ")) && text.contains(QStringLiteral("A ")),
             qPrintable(text));
    page()->controls()->fromLineBox()->setValue(3);
    page()->controls()->runFromButton()->click();
    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = window()->findChild<QMessageBox*>()) && box->isVisible());
    QCOMPARE(box->text(), text);
    QVERIFY(!box->isModal());
    box->button(QMessageBox::Yes)->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    QCOMPARE(m_rig.elab->position(Axis::X), 0); // line 2 did not run
    QCOMPARE(m_rig.elab->position(Axis::Y), 100);
}

void TestProgramPage::page_fitsTheLaptopScreen()
{
    QVERIFY(window()->openMachine(m_rig.writeFile(m_rig.machineJson())));
    const QSize available = QGuiApplication::primaryScreen()->availableGeometry().size();
    const QSize minimum = window()->minimumSizeHint().expandedTo(window()->minimumSize());
    QVERIFY2(minimum.width() <= available.width() && minimum.height() <= available.height(),
             qPrintable(QStringLiteral("%1x%2").arg(minimum.width()).arg(minimum.height())));
    setProgram(QStringLiteral("G91\nG0 X1 Y2\nG0 A90\nM0 (Load the part)\nM2\n"));
    QCoreApplication::processEvents();
    QWidget* dock = window()->dockOf(page());
    QVERIFY(dock && dock->isVisible());
    // The page's width fits the dock: nothing scrolls sideways, every text can be read.
    QVERIFY2(
        page()->minimumSizeHint().width() <= dock->width(),
        qPrintable(
            QStringLiteral("%1 > %2").arg(page()->minimumSizeHint().width()).arg(dock->width())));
    // Nor up and down: the default bottom dock holds the whole page (nothing hides below).
    auto* scroll = qobject_cast<QAbstractScrollArea*>(page()->parentWidget()->parentWidget());
    QVERIFY(scroll);
    QVERIFY2(page()->minimumSizeHint().height() <= scroll->viewport()->height(),
             qPrintable(QStringLiteral("%1 > %2")
                            .arg(page()->minimumSizeHint().height())
                            .arg(scroll->viewport()->height())));
    for (QWidget* w : page()->findChildren<QWidget*>()) {
        if (qobject_cast<QAbstractButton*>(w) || qobject_cast<QLabel*>(w)) {
            const QString problem = textProblem(w);
            QVERIFY2(problem.isEmpty(),
                     qPrintable(w->objectName() + QStringLiteral(": ") + problem));
        }
    }
}

// Issue 28, item 0: every connection is a machine. The connection bar's controller runs
// programs as it is, with no step in between; before it connects, its machine is there
// (axes shown, the program checked against them) but nothing can run.
void TestProgramPage::connection_singleController_isTheMachineProgramsRunOn()
{
    window()->connectionBar()->setSelectedModel(QStringLiteral("elab"));
    QVERIFY(window()->context()->isConnectionMachine());
    setProgram(QStringLiteral("G91\nG0 X10\nM2\n"));
    QVERIFY(!page()->controls()->runButton()->isEnabled()); // not connected
    window()->connectionBar()->setPortSpec(QStringLiteral("sim"));
    window()->connectionBar()->connectNow();
    QVERIFY(m_rig.f->waitConnected());
    QVERIFY(window()->context()->isConnectionMachine());
    QVERIFY(page()->runner());
    QTRY_VERIFY_WITH_TIMEOUT(m_rig.machine()->state() != machine::MachineState::Disconnected,
                             10000);
    // The controller's own axes in steps: the program is checked against them.
    QTRY_VERIFY2(page()->editor()->errorLines().isEmpty() &&
                     page()->checkText().startsWith(QStringLiteral("Checked")),
                 qPrintable(page()->checkText()));
}

// The connection's machine keeps what the operator set for the controller before machines
// existed (the former Units…, Soft limits… and Referencing settings, still read): X's units
// (400 steps per mm), its soft limits converted to mm, the referencing order and direction;
// Y without units stays in steps.
void TestProgramPage::connection_keepsTheControllersUnitsLimitsAndReferencing()
{
    QSettings settings;
    settings.setValue(QStringLiteral("units/elab/X/stepsPerUnit"), 400.0);
    settings.setValue(QStringLiteral("units/elab/X/unit"), QStringLiteral("mm"));
    settings.setValue(QStringLiteral("softLimits/elab/X/rangeSet"), true);
    settings.setValue(QStringLiteral("softLimits/elab/X/minimum"), -400);
    settings.setValue(QStringLiteral("softLimits/elab/X/maximum"), 40000);
    settings.setValue(QStringLiteral("reference/elab/X/direction"), -1);
    settings.setValue(QStringLiteral("reference/elab/X/order"), 3);
    settings.setValue(QStringLiteral("reference/elab/Z/direction"), 1);
    settings.setValue(QStringLiteral("reference/elab/Z/order"), 1);
    window()->connectionBar()->setSelectedModel(QStringLiteral("elab"));
    window()->connectionBar()->setPortSpec(QStringLiteral("sim"));
    window()->connectionBar()->connectNow();
    QVERIFY(m_rig.f->waitConnected());
    const machine::MachineDescription& d = m_rig.machine()->description();
    const machine::MachineAxis& x = *d.axis(QStringLiteral("X"));
    QCOMPARE(x.unit, machine::AxisUnit::Millimetre);
    QCOMPARE(x.stepsPerUnit, 400.0);
    QCOMPARE(*x.softMinimum, -1.0);
    QCOMPARE(*x.softMaximum, 100.0);
    QCOMPARE(d.axis(QStringLiteral("Y"))->unit, machine::AxisUnit::Step);
    QCOMPARE(x.referenceOrder, 3);
    QCOMPARE(x.referenceDirection, -1);
    QCOMPARE(d.axis(QStringLiteral("Z"))->referenceDirection, 1);
    QCOMPARE(d.axis(QStringLiteral("Z"))->referenceOrder, 1);
    // The position display reads the same machine: X in mm.
    QTRY_COMPARE(window()->positionPanel()->machineDro()->unitText(QStringLiteral("X")),
                 QStringLiteral("mm"));
    // The next tests start without these settings.
    settings.remove(QStringLiteral("units"));
    settings.remove(QStringLiteral("softLimits"));
    settings.remove(QStringLiteral("reference"));
}

// Issue 28: the check judges the board's rules by what this session wrote. Before the setup is
// written the E-LAB refuses every move and its start speed is unknown, so G1 is refused; once
// the Setup page (here the rig) wrote it, the page checks the text again by itself.
void TestProgramPage::check_setupWrittenMeanwhile_checkedAgainRunEnabled()
{
    QVERIFY(m_rig.openAndConnect(m_rig.machineJson(),
                                 {QStringLiteral("table"), QStringLiteral("rotary")}));
    setProgram(QStringLiteral("G91\nG1 X0.01 F6\nM2\n")); // 40 steps/s: below the start speed
    QVERIFY2(!page()->checkText().contains(QStringLiteral("no errors")),
             qPrintable(page()->checkText()));
    QVERIFY(!page()->controls()->runButton()->isEnabled());
    QVERIFY(m_rig.writeElabSetup());
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 10000);
    QVERIFY2(page()->checkText().contains(QStringLiteral("no errors")),
             qPrintable(page()->checkText()));
}

// Issue 50 item 1: a feed far above what the board's contour stream runs is no error: the
// check's line says the note (its line and the F that runs), its tool tip every note, and Run
// stays enabled.
void TestProgramPage::check_feedAboveTheHighest_noteShownRunStaysEnabled()
{
    QVERIFY(m_rig.openAndConnect(m_rig.machineJson(),
                                 {QStringLiteral("table"), QStringLiteral("rotary")}));
    QVERIFY(m_rig.writeElabSetup());
    setProgram(QStringLiteral("G91\nG1 X1 F600000\nM2\n"));
    QTRY_VERIFY_WITH_TIMEOUT(page()->controls()->runButton()->isEnabled(), 10000);
    const QString text = page()->checkText();
    QVERIFY2(text.contains(QStringLiteral("no errors; 1 note(s), line 2: F600000 runs at F")),
             qPrintable(text));
    QVERIFY2(page()->checkToolTip().startsWith(QStringLiteral("2:7: F600000 runs at F")),
             qPrintable(page()->checkToolTip()));
}

// Issue 28, item 3: after Zero X/Y, "G0 X0 Y0" goes to the work zero the position display
// shows (not to machine 0); the preview says which coordinates it shows and draws the path in
// them; a target beyond the soft limits in machine coordinates is refused by the check.
void TestProgramPage::run_afterZeroXY_programInWorkCoordinatesAtTheBoard()
{
    QVERIFY(m_rig.openAndConnect(m_rig.machineJson(QStringLiteral("Limited table"),
                                                   QStringLiteral(", \"softLimits\": [0, 100]"))));
    QVERIFY(m_rig.referenceTable());
    const qint64 xHome = m_rig.elab->position(Axis::X); // the board counts from power-on
    const qint64 yHome = m_rig.elab->position(Axis::Y);
    setProgram(QStringLiteral("G91 G0 X2 Y1\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    ui::MachineDro* dro = window()->positionPanel()->machineDro();
    QTRY_VERIFY(dro->zeroAxis(QStringLiteral("X")));
    QVERIFY(dro->zeroAxis(QStringLiteral("Y")));
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("0.000"));

    setProgram(QStringLiteral("G90 G0 X0.5 Y0.25\nG0 X0 Y0\nM2\n"));
    const QString coordinates = page()->preview()->coordinatesText();
    QVERIFY2(coordinates.contains(QStringLiteral("X 0 at machine 2.000 mm")),
             qPrintable(coordinates));
    QVERIFY(page()->preview()->pathView()->points().contains(QPointF(0.5, 0.25)));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    // At the board: back at the work zero, 2 mm and 1 mm from the reference (400 steps/mm).
    QCOMPARE(m_rig.elab->position(Axis::X) - xHome, 800);
    QCOMPARE(m_rig.elab->position(Axis::Y) - yHome, 400);
    QVERIFY(m_rig.elab->still());
    QCOMPARE(dro->displayedValue(QStringLiteral("X")), QStringLiteral("0.000"));

    // The check judges the soft limits in machine coordinates: work -2.5 is machine -0.5.
    setProgram(QStringLiteral("G90 G0 X-2.5\nM2\n"));
    QVERIFY2(page()->checkText().contains(QStringLiteral("in machine coordinates")),
             qPrintable(page()->checkText()));
}

// Issue 33: a program with parameters and an O-word loop is checked with its errors at the
// file's lines, previewed with the file's line count, and run: the board moved each pass.
void TestProgramPage::linuxcncLanguage_errorsAtFileLines_runMovesTheDevice()
{
    QVERIFY(m_rig.openAndConnect());
    setProgram(QStringLiteral("G91\no1 repeat [2]\n  G0 X[1/#5]\no1 endrepeat\nM2\n"));
    QTRY_COMPARE(page()->editor()->errorLines(), QList<int>{3});
    QVERIFY2(page()->editor()->errorAt(3).contains(QStringLiteral("division by zero")),
             qPrintable(page()->editor()->errorAt(3)));
    QVERIFY(!page()->controls()->runButton()->isEnabled());

    const qint64 x0 = m_rig.elab->position(Axis::X);
    setProgram(QStringLiteral("G91\n#<d>=0.25\no1 repeat [2]\n  G0 X#<d>\n  #<d>=[#<d>*2]\n"
                              "o1 endrepeat\nM2\n"));
    QTRY_VERIFY(page()->controls()->runButton()->isEnabled());
    QVERIFY2(page()->editor()->errorLines().isEmpty(), qPrintable(page()->checkText()));
    const QString figures = page()->preview()->figuresText();
    QVERIFY2(figures.contains(QStringLiteral("7 line")), qPrintable(figures));
    // Its lines do not run in file order: no run from a line, and the button says why.
    QVERIFY(!page()->controls()->runFromButton()->isEnabled());
    QVERIFY2(page()->controls()->runFromButton()->toolTip().contains(QStringLiteral("O words")),
             qPrintable(page()->controls()->runFromButton()->toolTip()));
    page()->controls()->runButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(runState(RunState::Finished), 20000);
    // 0.25 mm then 0.5 mm at 400 steps/mm.
    QCOMPARE(m_rig.elab->position(Axis::X) - x0, 300);
    QVERIFY(m_rig.elab->still());
}

// Issue 47 item 12: before a work zero is set a CAM job fails the soft limits, and the operator
// must still see the part to place the zero: the path as the check walked it, in work
// coordinates, what lies beyond the limits in the error colour, the extents, and the list of
// the errors in the preview's last tab. Run stays off.
void TestProgramPage::preview_softLimitErrors_pathShownWithTheErrors()
{
    QVERIFY(openLimitedTable());
    setProgram(kBeyondTheLimits);
    QVERIFY2(page()->checkText().startsWith(QStringLiteral("1 error")) &&
                 page()->checkText().contains(QStringLiteral("line 3: X reaches 120 mm")),
             qPrintable(page()->checkText()));
    QVERIFY(!page()->controls()->runButton()->isEnabled());
    ui::ProgramPreviewView* preview = page()->preview();
    // The path stays in view, marked as not runnable.
    QVERIFY(preview->pathView()->isVisible());
    QVERIFY(preview->showsErrors());
    const QList<QPointF> points = preview->pathView()->points();
    QVERIFY(points.contains(QPointF(10, 5)));
    QVERIFY(points.contains(QPointF(120, 5)));
    QVERIFY2(preview->figuresText().contains(QStringLiteral("not runnable")),
             qPrintable(preview->figuresText()));
    // The one point beyond the limits, marked where the path leaves them.
    QCOMPARE(preview->pointsBeyondLimits(), 1);
    QCOMPARE(preview->limitExits(), QList<QPointF>{QPointF(120, 5)});
    // The extents as the walk reached them, X's end beyond its limits in the error colour.
    QTableWidget* extents = preview->extentsTable();
    QTableWidgetItem* xTo = nullptr;
    for (int r = 0; r < extents->rowCount(); ++r)
        if (extents->item(r, 0)->text() == QLatin1String("X"))
            xTo = extents->item(r, 2);
    QVERIFY(xTo);
    QCOMPARE(xTo->text(), QStringLiteral("120.000 mm"));
    QCOMPARE(xTo->foreground().color(), QColor(0xb0, 0, 0));
    // The list of the errors, one tab away, with the error.
    QTabWidget* tabs = preview->tabs();
    const int errorsTab = preview->errorsTabIndex();
    QVERIFY(tabs->isTabEnabled(errorsTab));
    QVERIFY(tabs->isTabEnabled(0));
    QCOMPARE(tabs->tabText(errorsTab), QStringLiteral("Errors (1)"));
    ui::ProgramErrorList* list = page()->errorList();
    QCOMPARE(list->errorCount(), 1);
    const QString entry = list->list()->item(0)->text();
    QVERIFY2(entry.startsWith(QStringLiteral("line 3: X reaches 120 mm")) &&
                 entry.contains(QStringLiteral("soft limits 0..100 mm")),
             qPrintable(entry));
    tabs->setCurrentIndex(errorsTab);
    QTRY_VERIFY(list->isVisible());
    QVERIFY(!page()->controls()->runButton()->isEnabled()); // the check means what it says

    // Within the limits: the same path, nothing marked, Run on.
    tabs->setCurrentIndex(0);
    setProgram(kWithinTheLimits);
    QTRY_VERIFY2(page()->controls()->runButton()->isEnabled(), qPrintable(page()->checkText()));
    QVERIFY(!preview->showsErrors());
    QCOMPARE(preview->pointsBeyondLimits(), 0);
    QVERIFY(!tabs->isTabEnabled(errorsTab));
    QVERIFY(preview->pathView()->points().contains(QPointF(90, 5)));
}

// A program that does not parse has no path: the list of its errors alone.
void TestProgramPage::preview_parseErrors_listOnly()
{
    QVERIFY(window()->openMachine(m_rig.writeFile(m_rig.machineJson())));
    setProgram(kDoesNotParse);
    QVERIFY2(page()->checkText().startsWith(QStringLiteral("1 error")),
             qPrintable(page()->checkText()));
    ui::ProgramPreviewView* preview = page()->preview();
    QTabWidget* tabs = preview->tabs();
    QTRY_VERIFY(page()->errorList()->isVisible());
    QCOMPARE(tabs->currentIndex(), preview->errorsTabIndex());
    for (int i = 0; i < tabs->count(); ++i)
        QCOMPARE(tabs->isTabEnabled(i), i == preview->errorsTabIndex());
    QVERIFY(!preview->showsErrors());
    QVERIFY(!preview->pathView()->isVisible());
    QVERIFY(preview->pathView()->points().isEmpty());
    QCOMPARE(preview->pointsBeyondLimits(), 0);
    QCOMPARE(page()->errorList()->errorCount(), 1);
    QVERIFY(!page()->controls()->runButton()->isEnabled());
}

// No errors, errors beside a path, errors without one, and back: the page, the preview and the
// room the path (or the list) is shown in keep their size and place.
void TestProgramPage::preview_errorsComeAndGo_layoutHoldsStill()
{
    QVERIFY(openLimitedTable());
    ui::ProgramPreviewView* preview = page()->preview();
    QTabWidget* tabs = preview->tabs();
    const auto places = [&] {
        return QList<QRect>{placeOf(page()),
                            placeOf(preview),
                            placeOf(tabs),
                            placeOf(tabs->currentWidget()),
                            placeOf(page()->editor()),
                            placeOf(page()->controls()->runButton()),
                            placeOf(page()->findChild<QWidget*>(QStringLiteral("programCheck"))),
                            placeOf(preview->summary()),
                            QRect(QPoint(), window()->size())};
    };
    setProgram(kWithinTheLimits);
    QTRY_VERIFY2(page()->controls()->runButton()->isEnabled(), qPrintable(page()->checkText()));
    QCoreApplication::processEvents();
    const QList<QRect> clean = places();
    const QRect drawing = placeOf(preview->pathView());

    setProgram(kBeyondTheLimits);
    QTRY_VERIFY(preview->showsErrors());
    QCoreApplication::processEvents();
    QCOMPARE(places(), clean);
    QCOMPARE(placeOf(preview->pathView()), drawing); // the path kept its room

    setProgram(kDoesNotParse);
    QTRY_VERIFY(page()->errorList()->isVisible());
    QCoreApplication::processEvents();
    QCOMPARE(places(), clean);
    QCOMPARE(placeOf(page()->errorList()), drawing); // the list where the path was

    setProgram(kWithinTheLimits);
    QTRY_VERIFY(preview->pathView()->isVisible());
    QCoreApplication::processEvents();
    QCOMPARE(places(), clean);
    QCOMPARE(placeOf(preview->pathView()), drawing);
}

STEPDECK_TEST_MAIN_WITH(TestProgramPage, runOnLaptopScreen<TestProgramPage>)
#include "tst_programpage.moc"
