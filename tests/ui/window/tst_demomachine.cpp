// The built-in demo (issue 31, "What a newcomer sees first"; `stepdeck --demo`, tools/run): the
// window opens a simulated table in mm with its setup written and a program open in the Run
// workspace; Reference all, and the program passes its check and runs; a demo file the
// newcomer changed is kept.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "position/ReferencePanel.h"
#include "program/ProgramControls.h"
#include "program/ProgramEditor.h"
#include "program/ProgramPage.h"
#include "program/ProgramRunner.h"
#include "safety/SafetyBar.h"
#include "window/DemoMachine.h"
#include "window/Workspaces.h"
#include <QDir>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestDemoMachine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init()
    {
        QDir(ui::DemoMachine::directory()).removeRecursively();
        m_f = std::make_unique<UiFixture>();
        m_f->window->show();
        QVERIFY(QTest::qWaitForWindowActive(m_f->window.get()));
    }
    void cleanup() { m_f.reset(); }
    void open_referenceAll_programChecksAndRuns();
    void open_keepsAnEditedProgram();

private:
    ui::MainWindow* window() const { return m_f->window.get(); }
    std::unique_ptr<UiFixture> m_f;
};

void TestDemoMachine::open_referenceAll_programChecksAndRuns()
{
    QString error;
    QVERIFY2(ui::DemoMachine::open(window(), &error), qPrintable(error));
    machine::Machine* m = window()->context()->machine();
    QVERIFY(m);
    QCOMPARE(m->description().axes.size(), qsizetype(3));
    ControllerSession* table = m->session(QStringLiteral("table"));
    QTRY_COMPARE_WITH_TIMEOUT(table->linkState(), LinkState::Connected, 10000);
    QCOMPARE(window()->workspaces()->current(), ui::Workspaces::Workspace::Run);
    ui::ProgramPage* page = window()->programPage();
    QVERIFY(page->editor()->toPlainText().contains(QStringLiteral("StepDeck demo")));
    // Not referenced yet: the check says what to do first.
    QTRY_VERIFY_WITH_TIMEOUT(page->checkText().contains(QStringLiteral("reference")), 10000);
    window()->referencePanel()->referenceAll();
    QTRY_VERIFY_WITH_TIMEOUT(!window()->referencePanel()->isRunning(), 60000);
    QVERIFY2(window()->referencePanel()->messageText().contains(QStringLiteral("referenced")),
             qPrintable(window()->referencePanel()->messageText()));
    // The setup from the machine file was written on connect: the contours' F240 is allowed.
    QTRY_VERIFY2_WITH_TIMEOUT(page->checkText().contains(QStringLiteral("no errors")),
                              qPrintable(page->checkText()), 10000);
    QTRY_VERIFY(page->controls()->runButton()->isEnabled());
    page->controls()->runButton()->click();
    // The device moves (the simulator's own status): then STOP, and it stands.
    QTRY_VERIFY_WITH_TIMEOUT(table->status().anyMoving(), 10000);
    window()->safetyBar()->stopButton()->click();
    QTRY_VERIFY_WITH_TIMEOUT(program::isEnded(page->runner()->state()), 20000);
    QTRY_VERIFY_WITH_TIMEOUT(!table->status().anyMoving(), 10000);
}

void TestDemoMachine::open_keepsAnEditedProgram()
{
    QVERIFY(QDir().mkpath(ui::DemoMachine::directory()));
    QFile own(ui::DemoMachine::programPath());
    QVERIFY(own.open(QIODevice::WriteOnly));
    own.write("(my own)\nG0 X1\nM2\n");
    own.close();
    QString error;
    QVERIFY2(ui::DemoMachine::open(window(), &error), qPrintable(error));
    QVERIFY(
        window()->programPage()->editor()->toPlainText().startsWith(QStringLiteral("(my own)")));
    QVERIFY(QFile::exists(ui::DemoMachine::machinePath()));
}

STEPDECK_TEST_MAIN(TestDemoMachine)
#include "tst_demomachine.moc"
