// The File menu's machine actions (issue 19): the recent machines (order, cap, the submenu
// asking the window to open one), New machine… starting from the connected controller, and
// the main window's File menu saying what the validator found in an opened file.
#include "../UiTestSupport.h"
#include "MachineEditorTestSupport.h"
#include "TestMain.h"
#include "connection/ConnectionSettings.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineFileActions.h"
#include "machine/RecentMachines.h"
#include "messages/StatusMessages.h"
#include "position/PositionPanel.h"
#include <QAbstractButton>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QTemporaryDir>

using namespace stepdeck;
using namespace stepdeck::test;
using machine::MachineDescription;
namespace recent = stepdeck::ui::recentmachines;

class TestMachineFileActions : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { recent::clear(); }
    void recent_mostRecentFirst_cappedWithoutDuplicates();
    void recentMenu_entry_requestsOpenAndMovesToFront();
    void fileMenu_hasMachineActions();
    void openRequested_windowOpensTheMachineOrNamesTheField_data();
    void openRequested_windowOpensTheMachineOrNamesTheField();
    void newMachine_connected_startsFromThatController();
    void newMachine_notConnected_opensValidNewMachine();
    void editorSaved_isRemembered();
    void edit_connectionMachine_startsFromItsAxesSavedFileOpens();
    void newMachine_whileEditorHasChanges_asksFirst();
    void closeWindow_editorHasChanges_asksCancelKeepsBothDiscardClosesBoth();
    void editorOpen_escInACell_stillStops();
    void editMachine_machineOpen_opensItsFile();
    void editorSaved_machineOpen_saysItStillRunsAndOffersReopen();

private:
    // A machine of one simulated E-LAB in mm, written to dir.
    static QString writeSimMachine(const QTemporaryDir& dir)
    {
        const QString path = dir.filePath(QStringLiteral("sim.machine.json"));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return {};
        file.write(R"({
  "format": "stepdeck-machine", "version": 1, "name": "Simulated table",
  "controllers": [ { "id": "table", "model": "elab", "port": "sim" } ],
  "axes": [ { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 } ]
})");
        return path;
    }
    static ui::MachineFileActions* actionsOf(ui::MainWindow* window)
    {
        return window->findChild<ui::MachineFileActions*>();
    }
};

void TestMachineFileActions::recent_mostRecentFirst_cappedWithoutDuplicates()
{
    QTemporaryDir dir;
    QStringList added;
    for (int i = 0; i < recent::kMaxRecentMachines + 3; ++i) {
        added.prepend(dir.filePath(QStringLiteral("m%1.machine.json").arg(i)));
        recent::add(added.first());
    }
    QCOMPARE(recent::list(), added.mid(0, recent::kMaxRecentMachines));
    const QString older = added.at(4);
    recent::add(older); // used again: to the front, once
    QCOMPARE(recent::list().first(), older);
    QCOMPARE(recent::list().count(older), 1);
    QCOMPARE(recent::list().size(), recent::kMaxRecentMachines);
    recent::add(QStringLiteral("  "));
    QCOMPARE(recent::list().first(), older);
}

void TestMachineFileActions::recentMenu_entry_requestsOpenAndMovesToFront()
{
    QWidget window;
    ui::MachineFileActions actions(nullptr, &window);
    const QString first = example(QStringLiteral("emis-xyzu.machine.json"));
    const QString second = example(QStringLiteral("laser-axes.machine.json"));
    recent::add(first);
    recent::add(second);
    Q_EMIT actions.recentMenu()->aboutToShow();
    QList<QAction*> entries;
    for (QAction* a : actions.recentMenu()->actions()) {
        if (a->data().isValid())
            entries << a;
    }
    QCOMPARE(entries.size(), 2);
    QCOMPARE(entries.at(0)->data().toString(), QFileInfo(second).absoluteFilePath());
    QSignalSpy requested(&actions, &ui::MachineFileActions::openRequested);
    entries.at(1)->trigger();
    QCOMPARE(requested.size(), 1);
    QCOMPARE(requested.at(0).at(0).toString(), QFileInfo(first).absoluteFilePath());
    QCOMPARE(recent::list().first(), QFileInfo(first).absoluteFilePath());
}

void TestMachineFileActions::fileMenu_hasMachineActions()
{
    UiFixture f;
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    QVERIFY(actions);
    QMenu* file = f.window->menuBar()->actions().first()->menu();
    QVERIFY(file->actions().contains(actions->newAction()));
    QVERIFY(file->actions().contains(actions->openAction()));
    QVERIFY(file->actions().contains(actions->editAction()));
    QVERIFY(file->actions().contains(actions->recentMenu()->menuAction()));
}

void TestMachineFileActions::openRequested_windowOpensTheMachineOrNamesTheField_data()
{
    QTest::addColumn<QString>("stepsPerUnit"); // of axes[2]
    QTest::addColumn<QString>("shown");
    QTest::newRow("valid") << "800"
                           << "opened: 2 controllers, 4 axes";
    QTest::newRow("invalid") << "-2"
                             << "axes[2].stepsPerUnit";
}

void TestMachineFileActions::openRequested_windowOpensTheMachineOrNamesTheField()
{
    QFETCH(QString, stepsPerUnit);
    QFETCH(QString, shown);
    QTemporaryDir dir;
    QFile source(example(QStringLiteral("elab-xyz-nanotec-rotary.machine.json")));
    QVERIFY(source.open(QIODevice::ReadOnly));
    QByteArray json = source.readAll();
    json.replace("\"stepsPerUnit\": 800", "\"stepsPerUnit\": " + stepsPerUnit.toUtf8());
    const QString path = dir.filePath(QStringLiteral("t.machine.json"));
    // The table's setup file, which the example names beside it.
    QVERIFY(QFile::copy(example(QStringLiteral("elab-table.setup.json")),
                        dir.filePath(QStringLiteral("elab-table.setup.json"))));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(json);
    file.close();

    UiFixture f;
    actionsOf(f.window.get())->open(path);
    QVERIFY2(f.window->messages()->currentText().contains(shown),
             qPrintable(f.window->messages()->currentText()));
    QCOMPARE(recent::list().first(), path);
}

void TestMachineFileActions::newMachine_connected_startsFromThatController()
{
    ui::connectionsettings::setResetLine(QStringLiteral("elab"), LineSettings::ResetLine::Dtr);
    UiFixture f;
    QVERIFY(f.connectSim());
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->newAction()->trigger();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QVERIFY(editor->isVisible());
    QVERIFY(!editor->isModal());
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    MachineDescription expected =
        MachineDescription::singleController(*elab, QStringLiteral("sim"));
    expected.controllers[0].resetLine = LineSettings::ResetLine::Dtr; // as connected
    QCOMPARE(editor->machine(), expected);
    QVERIFY(!editor->close()); // unsaved: asks first
    editor->pendingPrompt()->button(QMessageBox::Discard)->click();
    QTRY_VERIFY(!actions->editor());
}

void TestMachineFileActions::newMachine_notConnected_opensValidNewMachine()
{
    UiFixture f;
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->newAction()->trigger();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    // No axes yet: the validator says so, naming the axes table.
    QCOMPARE(editor->error().field, QStringLiteral("axes"));
    editor->axesTable()->addAxis();
    QVERIFY2(editor->machine(), qPrintable(editor->messageText()));
    QCOMPARE(editor->machine()->axes.first().name, QStringLiteral("X"));
    editor->close();
    if (editor->pendingPrompt())
        editor->pendingPrompt()->button(QMessageBox::Discard)->click();
    QTRY_VERIFY(!actions->editor());
}

void TestMachineFileActions::editorSaved_isRemembered()
{
    UiFixture f;
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->setCurrentMachine(example(QStringLiteral("emis-xyzu.machine.json")));
    actions->editAction()->trigger();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QVERIFY(editor->machine());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("copy.machine.json"));
    QVERIFY(editor->saveTo(path));
    QCOMPARE(recent::list().first(), path);
    editor->close();
    QTRY_VERIFY(!actions->editor());
}

// Issue 28, item 0: the connection bar's controller is a machine of one; Edit machine… (and
// the Position dock's "Units and limits…") edits its axes and saves them as a machine file,
// which the window then opens in its place.
void TestMachineFileActions::edit_connectionMachine_startsFromItsAxesSavedFileOpens()
{
    UiFixture f;
    QVERIFY(f.connectSim());
    QVERIFY(f.window->context()->isConnectionMachine());
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    auto* unitsButton =
        f.window->positionPanel()->findChild<QAbstractButton*>(QStringLiteral("editMachineAxes"));
    QVERIFY(unitsButton);
    unitsButton->click();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QVERIFY(editor->isModified()); // not saved anywhere yet
    const std::optional<MachineDescription> edited = editor->machine();
    QVERIFY(edited);
    QCOMPARE(*edited, f.window->context()->machine()->description());
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("elab.machine.json"));
    QVERIFY(editor->saveTo(path));
    QTRY_VERIFY(f.window->context()->hasMachine() && !f.window->context()->isConnectionMachine());
    QCOMPARE(f.window->context()->machinePath(), path);
    editor->close();
    QTRY_VERIFY(!actions->editor());
}

void TestMachineFileActions::newMachine_whileEditorHasChanges_asksFirst()
{
    UiFixture f;
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->setCurrentMachine(example(QStringLiteral("emis-xyzu.machine.json")));
    actions->editAction()->trigger();
    QPointer<ui::MachineEditor> first = actions->editor();
    QVERIFY(first);
    typeInto(first->nameEdit(), QStringLiteral("Changed"));
    actions->newAction()->trigger(); // one editor at a time: its changes are not dropped
    QCOMPARE(actions->editor(), first.data());
    QVERIFY(first->isVisible());
    QVERIFY(first->pendingPrompt());
    QCOMPARE(f.window->findChildren<ui::MachineEditor*>().size(), 1);
    first->pendingPrompt()->button(QMessageBox::Discard)->click();
    QTRY_VERIFY(!first);
    actions->newAction()->trigger();
    QVERIFY(actions->editor());
    QCOMPARE(actions->editor()->nameEdit()->text(), QStringLiteral("New machine"));
    actions->editor()->close();
}

// Closing the main window dropped the editor's unsaved edits with it: the window now stays
// open until the editor's question is answered; Cancel keeps both, Discard closes both.
void TestMachineFileActions::closeWindow_editorHasChanges_asksCancelKeepsBothDiscardClosesBoth()
{
    UiFixture f;
    f.window->show();
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->setCurrentMachine(example(QStringLiteral("emis-xyzu.machine.json")));
    actions->editAction()->trigger();
    QPointer<ui::MachineEditor> editor = actions->editor();
    QVERIFY(editor);
    typeInto(editor->nameEdit(), QStringLiteral("Changed"));
    QVERIFY(!f.window->close());
    QVERIFY(f.window->isVisible());
    QVERIFY(editor->isVisible());
    QVERIFY(editor->pendingPrompt());
    editor->pendingPrompt()->button(QMessageBox::Cancel)->click();
    QTRY_VERIFY(!editor->pendingPrompt());
    QVERIFY(f.window->isVisible());
    QVERIFY(editor->isVisible());
    QCOMPARE(editor->nameEdit()->text(), QStringLiteral("Changed"));

    QVERIFY(!f.window->close()); // asked again
    QVERIFY(editor->pendingPrompt());
    editor->pendingPrompt()->button(QMessageBox::Discard)->click();
    QTRY_VERIFY(!editor);
    QTRY_VERIFY(!f.window->isVisible());
}

void TestMachineFileActions::editorOpen_escInACell_stillStops()
{
    // The editor is a window of its own: Esc (STOP) and F1 (PANIC) must reach the machine
    // from it as from the main window (issue 7, rule 5).
    UiFixture f;
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->setCurrentMachine(example(QStringLiteral("emis-xyzu.machine.json")));
    actions->editAction()->trigger();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QVERIFY(QTest::qWaitForWindowActive(editor));
    QWidget* cell = editor->axesTable()->cell(0, "stepsPerUnit");
    cell->setFocus();
    QTRY_VERIFY(cell->hasFocus());
    QSignalSpy stop(f.window->stopAction(), &QAction::triggered);
    QSignalSpy panic(f.window->panicAction(), &QAction::triggered);
    QTest::keyClick(cell, Qt::Key_Escape);
    QCOMPARE(stop.size(), 1);
    QTest::keyClick(cell, Qt::Key_F1);
    QCOMPARE(panic.size(), 1);
    editor->close();
}

// Issue 31: with a machine open (here opened as `stepdeck --machine FILE` and the demo open
// it, not through the File menu), Edit machine… asked for a file. It edits that machine's own
// file at once, no file dialog.
void TestMachineFileActions::editMachine_machineOpen_opensItsFile()
{
    UiFixture f;
    QTemporaryDir dir;
    const QString path = writeSimMachine(dir);
    QVERIFY(f.window->openMachine(path));
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->editAction()->trigger();
    for (QWidget* w : QApplication::topLevelWidgets())
        QVERIFY2(!w->inherits("QFileDialog") || !w->isVisible(), "a file dialog opened");
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QCOMPARE(editor->path(), path);
    QCOMPARE(editor->nameEdit()->text(), QStringLiteral("Simulated table"));
    editor->close();
    QTRY_VERIFY(!actions->editor());
}

// Issue 31: saving the open machine's file does not change the machine that runs; the editor
// and the window's message line say so, and the editor offers Re-open machine. Saved as
// another file, it is not the open machine's and nothing is offered.
void TestMachineFileActions::editorSaved_machineOpen_saysItStillRunsAndOffersReopen()
{
    UiFixture f;
    QTemporaryDir dir;
    const QString path = writeSimMachine(dir);
    QVERIFY(f.window->openMachine(path));
    ui::MachineFileActions* actions = actionsOf(f.window.get());
    actions->editAction()->trigger();
    ui::MachineEditor* editor = actions->editor();
    QVERIFY(editor);
    QVERIFY(!editor->reopenButton()->isVisible());
    typeInto(editor->nameEdit(), QStringLiteral("Renamed table"));
    QVERIFY(editor->saveTo(dir.filePath(QStringLiteral("other.machine.json"))));
    QVERIFY(!editor->reopenButton()->isVisible());
    QVERIFY(editor->saveTo(path));
    QVERIFY(editor->reopenButton()->isVisible());
    QVERIFY2(editor->messageText().contains(
                 QStringLiteral("still runs on the description it was opened with")),
             qPrintable(editor->messageText()));
    QVERIFY2(f.window->messages()->currentText().contains(QStringLiteral("re-open it")),
             qPrintable(f.window->messages()->currentText()));
    QCOMPARE(f.window->context()->machine()->description().name,
             QStringLiteral("Simulated table")); // the running machine is unchanged
    editor->close();
    QTRY_VERIFY(!actions->editor());
}

STEPDECK_TEST_MAIN(TestMachineFileActions)
#include "tst_machinefileactions.moc"
