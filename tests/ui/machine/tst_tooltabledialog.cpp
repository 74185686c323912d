// The machine's tool table in the window (issue 29): program::MachineTools keeps LinuxCNC tool.tbl
// text per machine, the dialog saves it only when every line reads and shows the first error in a
// line reserved for it.
#include "TestMain.h"
#include "machine/ToolTableDialog.h"
#include "program/MachineTools.h"
#include <QLabel>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::ui;

class TestToolTableDialog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init() { QSettings().clear(); }
    void save_validTable_keptPerMachineAndRemembered();
    void save_invalidLine_errorShownNothingChangedLayoutStill();
    void load_otherMachine_itsOwnTable();
    void dialogOpen_otherMachineLoaded_showsItsTableNeverSavesTheOldText();

private:
    QTemporaryDir m_dir;
};

void TestToolTableDialog::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUnitTest-tooltable"));
    QVERIFY(m_dir.isValid());
}

void TestToolTableDialog::save_validTable_keptPerMachineAndRemembered()
{
    const QString file = m_dir.filePath(QStringLiteral("mill.machine.json"));
    program::MachineTools tools;
    tools.load(file);
    QVERIFY(tools.table().isEmpty());
    ToolTableDialog dialog(&tools);
    QSignalSpy changed(&tools, &program::MachineTools::changed);
    dialog.editor()->setPlainText(QStringLiteral("T1 P1 Z12.5 D6 ;6 mm end mill\nT2 Z-3"));
    QVERIFY(dialog.save());
    QCOMPARE(changed.size(), 1);
    QVERIFY(dialog.errorText().isEmpty());
    QCOMPARE(tools.table().tools().size(), 2);
    QCOMPARE(tools.table().find(1)->length, 12.5);
    QCOMPARE(tools.table().find(1)->text, QStringLiteral("6 mm end mill"));
    program::MachineTools reopened;
    reopened.load(file);
    QCOMPARE(reopened.table(), tools.table());
    QCOMPARE(reopened.text(), tools.text());
}

void TestToolTableDialog::save_invalidLine_errorShownNothingChangedLayoutStill()
{
    program::MachineTools tools;
    tools.load(m_dir.filePath(QStringLiteral("b.machine.json")));
    QList<program::ProgramError> errors;
    QVERIFY(tools.setText("T4 Z1", &errors));
    ToolTableDialog dialog(&tools);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    auto* error = dialog.findChild<QLabel*>(QStringLiteral("toolTableError"));
    QVERIFY(error);
    const int heightBefore = error->height();
    dialog.editor()->setPlainText(QStringLiteral("T4 Z1\nT5 K9"));
    QVERIFY(!dialog.save());
    QCOMPARE(
        dialog.errorText(),
        QStringLiteral("Not saved: 2:4: K9 is not a column of a tool table (T, P, Z, D, ...)"));
    QCOMPARE(error->height(), heightBefore); // the reserved line: nothing moves
    QCOMPARE(tools.table().tools().size(), 1);
    QCOMPARE(tools.text(), QByteArray("T4 Z1"));
}

void TestToolTableDialog::load_otherMachine_itsOwnTable()
{
    program::MachineTools tools;
    tools.load(m_dir.filePath(QStringLiteral("c.machine.json")));
    QVERIFY(tools.setText("T1 Z5", nullptr));
    tools.load(m_dir.filePath(QStringLiteral("d.machine.json")));
    QVERIFY(tools.table().isEmpty());
    tools.load(QString()); // no machine: nothing stored
    QVERIFY(tools.setText("T9 Z1", nullptr));
    tools.load(m_dir.filePath(QStringLiteral("c.machine.json")));
    QCOMPARE(tools.table().find(1)->length, 5.0);
    QVERIFY(!tools.table().find(9));
}

// The dialog stays open while another machine is opened: it shows that machine's table, says
// that unsaved edits were dropped, and Save then stores only what it shows, for the new machine.
void TestToolTableDialog::dialogOpen_otherMachineLoaded_showsItsTableNeverSavesTheOldText()
{
    program::MachineTools tools;
    const QString a = m_dir.filePath(QStringLiteral("e.machine.json"));
    const QString b = m_dir.filePath(QStringLiteral("f.machine.json"));
    tools.load(b);
    QVERIFY(tools.setText("T2 Z7 ;b's drill", nullptr));
    tools.load(a);
    QVERIFY(tools.setText("T1 Z5 ;a's mill", nullptr));
    ToolTableDialog dialog(&tools);
    const int errorTop = dialog.findChild<QLabel*>(QStringLiteral("toolTableError"))->y();
    dialog.editor()->moveCursor(QTextCursor::End);
    QTest::keyClicks(dialog.editor(), QStringLiteral(" (edited)")); // typed, unsaved
    tools.load(b);
    QCOMPARE(dialog.editor()->toPlainText(), QStringLiteral("T2 Z7 ;b's drill"));
    QVERIFY2(dialog.errorText().contains(QStringLiteral("dropped")),
             qPrintable(dialog.errorText()));
    QCOMPARE(dialog.findChild<QLabel*>(QStringLiteral("toolTableError"))->y(), errorTop);
    QVERIFY(dialog.save());
    QCOMPARE(tools.table().find(2)->length, 7.0);
    QVERIFY(!tools.table().find(1));
    tools.load(a);
    QCOMPARE(tools.table().find(1)->length, 5.0); // a's table was not touched
    QCOMPARE(dialog.editor()->toPlainText(), QStringLiteral("T1 Z5 ;a's mill"));
    QVERIFY(dialog.errorText().isEmpty()); // nothing edited: nothing to say
}

STEPDECK_TEST_MAIN(TestToolTableDialog)
#include "tst_tooltabledialog.moc"
