// The machine editor's Re-open machine (issue 31) on the window's machine of two controllers
// on pseudo-terminals (MachineWindowRig): the saved file is opened again through the ordinary
// open (every controller stopped and closed, new sessions, reconnected), its positions unknown
// until referenced as after any reconnect; refused with the reason while anything moves.
#include "MachineEditorTestSupport.h"
#include "MachineWindowRig.h"
#include "TestMain.h"
#include "machine/MachineContext.h"
#include "machine/MachineEditor.h"
#include "machine/MachineFileActions.h"
#include "machine/MachineMdi.h"
#include "messages/StatusMessages.h"
#include <QPointer>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestMachineReopen : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QVERIFY(m_rig.start()); }
    void cleanup() { m_rig.stop(); }
    void reopen_idle_opensTheSavedFileReconnectedPositionsUnknown();
    void reopen_whileMoving_refusesWithTheReason();
    void reopen_mdiLineHeldAtM0_refusesWithTheReason();

private:
    // Edit machine… on the open machine, renamed and saved over its file.
    ui::MachineEditor* editAndSave(const QString& name)
    {
        auto* actions = m_rig.window()->findChild<ui::MachineFileActions*>();
        actions->editAction()->trigger();
        ui::MachineEditor* editor = actions->editor();
        if (!editor || editor->path() != m_rig.window()->context()->machinePath())
            return nullptr;
        typeInto(editor->nameEdit(), name);
        editor->save();
        return editor->reopenButton()->isVisible() ? editor : nullptr;
    }

    MachineWindowRig m_rig;
};

void TestMachineReopen::reopen_idle_opensTheSavedFileReconnectedPositionsUnknown()
{
    QVERIFY(m_rig.openAndConnect());
    QVERIFY(m_rig.referenceTable());
    ui::MachineContext* context = m_rig.window()->context();
    QPointer<machine::Machine> before = m_rig.machine();
    const machine::MachineAxis* x = before->description().axis(QStringLiteral("X"));
    QCOMPARE(before->axisStatus(*x).known, machine::PositionKnowledge::Referenced);

    ui::MachineEditor* editor = editAndSave(QStringLiteral("Renamed table"));
    QVERIFY(editor);
    editor->reopenButton()->click();
    QVERIFY2(editor->messageText().contains(QStringLiteral("re-opened")),
             qPrintable(editor->messageText()));
    QVERIFY(!before); // the old machine was closed, not kept
    QCOMPARE(m_rig.machine()->description().name, QStringLiteral("Renamed table"));
    for (const QString& id : {QStringLiteral("table"), QStringLiteral("rotary")}) {
        ControllerSession* s = m_rig.machine()->session(id);
        QTRY_VERIFY_WITH_TIMEOUT(s->linkState() == LinkState::Connected, 10000);
    }
    // The board kept its reference; the host does not take it over (safety contract).
    ControllerSession* table = m_rig.machine()->session(QStringLiteral("table"));
    QTRY_VERIFY_WITH_TIMEOUT(!table->status().axes.isEmpty(), 10000);
    QVERIFY(!table->status().axes.value(Axis::X).referenced);
    const machine::MachineAxis* newX = m_rig.machine()->description().axis(QStringLiteral("X"));
    QCOMPARE(m_rig.machine()->axisStatus(*newX).known, machine::PositionKnowledge::Unknown);
    QCOMPARE(context->positionKnowledge(), machine::PositionKnowledge::Unknown);
    editor->close();
}

void TestMachineReopen::reopen_whileMoving_refusesWithTheReason()
{
    QVERIFY(m_rig.openAndConnect());
    ui::MachineEditor* editor = editAndSave(QStringLiteral("Renamed table"));
    QVERIFY(editor);
    machine::Machine* running = m_rig.machine();
    QString refusal;
    QVERIFY2(running->move({{QStringLiteral("X"), 40.0}}, false, &refusal), qPrintable(refusal));
    ControllerSession* table = running->session(QStringLiteral("table"));
    QTRY_VERIFY_WITH_TIMEOUT(table->status().axes.value(Axis::X).moving, 5000);
    editor->reopenButton()->click();
    QVERIFY2(editor->messageText().contains(QStringLiteral("Not re-opened")) &&
                 editor->messageText().contains(QStringLiteral("moving")),
             qPrintable(editor->messageText()));
    QVERIFY2(m_rig.window()->messages()->currentText().contains(QStringLiteral("not re-opened")),
             qPrintable(m_rig.window()->messages()->currentText()));
    QCOMPARE(m_rig.machine(), running); // the running machine is untouched
    QCOMPARE(running->description().name, QStringLiteral("Table with rotary axis"));
    m_rig.window()->stopAll();
    QTRY_VERIFY_WITH_TIMEOUT(!table->status().anyMoving(), 10000);
    editor->close();
}

// Nothing moves, but a line runs (held at its M0): the machine is not replaced under it.
void TestMachineReopen::reopen_mdiLineHeldAtM0_refusesWithTheReason()
{
    QVERIFY(m_rig.openAndConnect());
    ui::MachineEditor* editor = editAndSave(QStringLiteral("Renamed table"));
    QVERIFY(editor);
    machine::Machine* running = m_rig.machine();
    ui::MachineMdi* mdi = m_rig.window()->context()->mdi();
    QString refusal;
    QVERIFY2(mdi->runLine(QStringLiteral("M0"), &refusal), qPrintable(refusal));
    QTRY_VERIFY_WITH_TIMEOUT(mdi->isPausedAtOperatorStop(), 5000);
    editor->reopenButton()->click();
    QVERIFY2(editor->messageText().contains(QStringLiteral("an MDI line runs")),
             qPrintable(editor->messageText()));
    QCOMPARE(m_rig.machine(), running);
    mdi->abort();
    QTRY_VERIFY(!mdi->isBusy());
    editor->reopenButton()->click(); // now it may
    QVERIFY2(editor->messageText().contains(QStringLiteral("re-opened")),
             qPrintable(editor->messageText()));
    QCOMPARE(m_rig.machine()->description().name, QStringLiteral("Renamed table"));
    editor->close();
}

STEPDECK_TEST_MAIN(TestMachineReopen)
#include "tst_machinereopen.moc"
