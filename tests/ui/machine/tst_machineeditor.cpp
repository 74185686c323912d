// The machine editor's tables (issue 19): every typed value validated by
// MachineFile::validate with the offending cell marked, controllers renamed and rows removed
// as the operator expects, a message that never re-flows the layout, and the 1366x768 fit.
#include "../UiTestSupport.h"
#include "MachineEditorTestSupport.h"
#include "TestMain.h"
#include "common/ElidedLabel.h"
#include <QCheckBox>
#include <QHeaderView>
#include <QPushButton>
#include <QScrollBar>

using namespace stepdeck;
using namespace stepdeck::test;
using machine::MachineDescription;
using machine::MachineFile;

class TestMachineEditor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void typedValue_invalid_namesFieldAndMarksCell_data();
    void typedValue_invalid_namesFieldAndMarksCell();
    void typedValue_fixedAgain_clearsMark();
    void spindleMaxRpm_shownTypedAndCleared_inTheMachine();
    void crossControllerFeed_shownAndClicked_inTheMachine();
    void controllerId_renamed_axesFollow();
    void axisChoices_areTheControllersAxes();
    void namedBus_axisChoicesByName_machineKeepsTheNames();
    void removeAxis_removesTheRowBeingEdited();
    void removeController_removesTheRowBeingEdited();
    void addAxis_takesFreeNameAndControllerAxis();
    void message_longError_neverReflows();
    void sixAxes_fit1366x768();
};

void TestMachineEditor::typedValue_invalid_namesFieldAndMarksCell_data()
{
    QTest::addColumn<QString>("table"); // name, controllers or axes
    QTest::addColumn<int>("row");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");      // typed into a text cell, chosen in a choice cell
    QTest::addColumn<QString>("field");      // as MachineFile names it
    QTest::addColumn<QStringList>("marked"); // the cells marked, in that row

    // elab-xyz-nanotec-rotary: table (elab X Y Z) and rotary (nanotec X=1) as A.
    QTest::newRow("negative steps") << "axes" << 3 << "stepsPerUnit"
                                    << "-2"
                                    << "axes[3].stepsPerUnit" << QStringList{"stepsPerUnit"};
    QTest::newRow("letters") << "axes" << 1 << "stepsPerUnit"
                             << "4OO"
                             << "axes[1].stepsPerUnit" << QStringList{"stepsPerUnit"};
    QTest::newRow("zero steps") << "axes" << 0 << "stepsPerUnit"
                                << "0"
                                << "axes[0].stepsPerUnit" << QStringList{"stepsPerUnit"};
    QTest::newRow("min above max") << "axes" << 0 << "softMin"
                                   << "400"
                                   << "axes[0].softLimits" << QStringList{"softMin", "softMax"};
    QTest::newRow("max left out") << "axes" << 1 << "softMax"
                                  << ""
                                  << "axes[1].softLimits" << QStringList{"softMin", "softMax"};
    QTest::newRow("jog too fast") << "axes" << 2 << "maxJogSpeed"
                                  << "100"
                                  << "axes[2].maxJogSpeed" << QStringList{"maxJogSpeed"};
    QTest::newRow("jog nan") << "axes" << 2 << "maxJogSpeed"
                             << "nan"
                             << "axes[2].maxJogSpeed" << QStringList{"maxJogSpeed"};
    QTest::newRow("jog acceleration negative")
        << "axes" << 2 << "jogAcceleration"
        << "-5"
        << "axes[2].jogAcceleration" << QStringList{"jogAcceleration"};
    QTest::newRow("duplicate name") << "axes" << 1 << "name"
                                    << "X"
                                    << "axes[1].name" << QStringList{"name"};
    // A on the table's X, which X drives already: the axis cell is marked, not the controller.
    QTest::newRow("controller axis taken") << "axes" << 3 << "controller"
                                           << "table"
                                           << "axes[3].axis" << QStringList{"axis"};
    QTest::newRow("axis twice") << "axes" << 1 << "axis"
                                << "X"
                                << "axes[1].axis" << QStringList{"axis"};
    QTest::newRow("bad id") << "controllers" << 0 << "id"
                            << "1table"
                            << "controllers[0].id" << QStringList{"id"};
    QTest::newRow("duplicate id") << "controllers" << 1 << "id"
                                  << "table"
                                  << "controllers[1].id" << QStringList{"id"};
    QTest::newRow("no port") << "controllers" << 0 << "port"
                             << ""
                             << "controllers[0].port" << QStringList{"port"};
    QTest::newRow("bus address 0") << "controllers" << 1 << "axes"
                                   << "X=0"
                                   << "controllers[1].axes.X" << QStringList{"axes"};
    QTest::newRow("bus text") << "controllers" << 1 << "axes"
                              << "X:1"
                              << "controllers[1].axes" << QStringList{"axes"};
    QTest::newRow("no name") << "name" << 0 << ""
                             << ""
                             << "name" << QStringList{""};
    // Issue 29: the spindle scale beside the name.
    QTest::newRow("maxRpm zero") << "spindle" << 0 << ""
                                 << "0"
                                 << "spindle.maxRpm" << QStringList{""};
    QTest::newRow("maxRpm negative") << "spindle" << 0 << ""
                                     << "-24000"
                                     << "spindle.maxRpm" << QStringList{""};
    QTest::newRow("maxRpm letters") << "spindle" << 0 << ""
                                    << "24k"
                                    << "spindle.maxRpm" << QStringList{""};
}

void TestMachineEditor::typedValue_invalid_namesFieldAndMarksCell()
{
    QFETCH(QString, table);
    QFETCH(int, row);
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(QString, field);
    QFETCH(QStringList, marked);
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    QVERIFY(editor->error().field.isEmpty());
    QVERIFY(editor->markedCells().isEmpty());

    QWidget* cell = editorCell(editor.get(), table, row, key);
    QVERIFY(cell);
    if (qobject_cast<QComboBox*>(cell))
        choose(cell, value);
    else
        typeInto(cell, value);

    QCOMPARE(editor->error().field, field);
    QVERIFY2(editor->messageText().startsWith(field + QStringLiteral(": ")),
             qPrintable(editor->messageText()));
    QVERIFY(!editor->machine());
    QList<QWidget*> expected;
    for (const QString& k : marked)
        expected << editorCell(editor.get(), table, row, k);
    QCOMPARE(editor->markedCells(), expected);
    for (QWidget* w : expected)
        QVERIFY(!w->styleSheet().isEmpty());
}

void TestMachineEditor::typedValue_fixedAgain_clearsMark()
{
    auto editor = editorWith(QStringLiteral("emis-xyzu.machine.json"));
    QWidget* cell = editor->axesTable()->cell(2, "stepsPerUnit");
    const QString original = qobject_cast<QLineEdit*>(cell)->text();
    typeInto(cell, QStringLiteral("-1"));
    QCOMPARE(editor->markedCells(), QList<QWidget*>{cell});
    typeInto(cell, original);
    QVERIFY(editor->error().field.isEmpty());
    QVERIFY(editor->markedCells().isEmpty());
    QVERIFY(cell->styleSheet().isEmpty());
    QVERIFY(editor->machine());
}

// Issue 29: the field shows the file's maxRpm, a typed one is the machine's, and an empty
// field is a machine without a spindle scale; the window keeps its height.
void TestMachineEditor::spindleMaxRpm_shownTypedAndCleared_inTheMachine()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    QLineEdit* maxRpm = editor->maxRpmEdit();
    QVERIFY(maxRpm->text().isEmpty()); // the example has none
    QVERIFY(!editor->machine()->spindle.maxRpm);
    const int height = editor->minimumSizeHint().height();
    typeInto(maxRpm, QStringLiteral("24000"));
    QVERIFY2(editor->error().field.isEmpty(), qPrintable(editor->messageText()));
    QCOMPARE(editor->machine()->spindle.maxRpm, 24000.0);
    QVERIFY(editor->isModified());
    QCOMPARE(editor->minimumSizeHint().height(), height);

    machine::MachineDescription d = *editor->machine();
    d.spindle.maxRpm = 18000.5;
    d.spindle.laser = true; // no field of its own (issue 50): kept as the file has it
    editor->setMachine(d);
    QCOMPARE(maxRpm->text(), QStringLiteral("18000.5"));
    QCOMPARE(editor->machine()->spindle.maxRpm, 18000.5);
    QVERIFY(editor->machine()->spindle.laser);
    typeInto(maxRpm, QString());
    QVERIFY(editor->machine());
    QVERIFY(!editor->machine()->spindle.maxRpm);
    QVERIFY(editor->machine()->spindle.laser);
}

// Issue 30: the box shows the file's crossControllerFeed (on without the key) and a click is the
// machine's, with the window's height kept.
void TestMachineEditor::crossControllerFeed_shownAndClicked_inTheMachine()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    auto* box = editor->findChild<QCheckBox*>(QStringLiteral("machineCrossControllerFeed"));
    QVERIFY(box);
    QVERIFY(box->isChecked());
    QVERIFY(editor->machine()->crossControllerFeed);
    const int height = editor->minimumSizeHint().height();
    box->click();
    QVERIFY(!editor->machine()->crossControllerFeed);
    QVERIFY(editor->isModified());
    QCOMPARE(editor->minimumSizeHint().height(), height);
    machine::MachineDescription d = *editor->machine();
    d.crossControllerFeed = true;
    editor->setMachine(d);
    QVERIFY(box->isChecked());
    QVERIFY(!editor->isModified());
}

void TestMachineEditor::controllerId_renamed_axesFollow()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    typeInto(editor->controllersTable()->cell(1, "id"), QStringLiteral("turntable"));
    QVERIFY2(editor->error().field.isEmpty(), qPrintable(editor->messageText()));
    QVERIFY(editor->markedCells().isEmpty());
    const auto machine = editor->machine();
    QVERIFY2(machine, qPrintable(editor->messageText()));
    QCOMPARE(machine->axis(QStringLiteral("A"))->controller, QStringLiteral("turntable"));
    QCOMPARE(machine->axis(QStringLiteral("X"))->controller, QStringLiteral("table"));
}

void TestMachineEditor::axisChoices_areTheControllersAxes()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    auto choices = [&](int row) {
        auto* combo = qobject_cast<QComboBox*>(editor->axesTable()->cell(row, "axis"));
        QStringList items;
        for (int i = 0; i < combo->count(); ++i)
            items << combo->itemText(i);
        return items;
    };
    QCOMPARE(choices(0), (QStringList{"X", "Y", "Z"})); // the E-LAB's axes
    QCOMPARE(choices(3), QStringList{"X"});             // the Nanotec bus map X=1
    typeInto(editor->controllersTable()->cell(1, "axes"), QStringLiteral("X=1 Z=3"));
    QCOMPARE(choices(3), (QStringList{"X", "Z"}));
    choose(editor->axesTable()->cell(3, "axis"), QStringLiteral("Z"));
    QVERIFY2(editor->machine(), qPrintable(editor->messageText()));
    QCOMPARE(editor->machine()->axis(QStringLiteral("A"))->axis, Axis::Z);
    // Z leaves the map: the choice stays, marked, until the operator picks another.
    typeInto(editor->controllersTable()->cell(1, "axes"), QStringLiteral("X=1"));
    QCOMPARE(choices(3), (QStringList{"X", "Z"}));
    QCOMPARE(editor->error().field, QStringLiteral("axes[3].axis"));
    choose(editor->axesTable()->cell(3, "axis"), QStringLiteral("X"));
    QVERIFY(editor->error().field.isEmpty());
    QCOMPARE(choices(3), QStringList{"X"});
}

// Issue 32: the bus cell names the drives; the axis column offers them by those names, and
// the machine read from the editor keeps them (saved as a version 2 list).
void TestMachineEditor::namedBus_axisChoicesByName_machineKeepsTheNames()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    auto* combo = qobject_cast<QComboBox*>(editor->axesTable()->cell(3, "axis"));
    typeInto(editor->controllersTable()->cell(1, "axes"), QStringLiteral("lift=5, tilt=6"));
    QStringList items;
    for (int i = 0; i < combo->count(); ++i)
        items << combo->itemText(i);
    QCOMPARE(items, (QStringList{"lift", "tilt"}));
    choose(combo, QStringLiteral("tilt"));
    const std::optional<machine::MachineDescription> m = editor->machine();
    QVERIFY2(m, qPrintable(editor->messageText()));
    QCOMPARE(m->axis(QStringLiteral("A"))->axis, Axis::Y);
    QCOMPARE(m->controllers.at(1).busAddresses, (QMap<Axis, int>{{Axis::X, 5}, {Axis::Y, 6}}));
    QCOMPARE(m->controllers.at(1).axisNames.name(Axis::Y), QStringLiteral("tilt"));
    // Renaming the drive renames the choice and keeps it chosen.
    typeInto(editor->controllersTable()->cell(1, "axes"), QStringLiteral("lift=5 swivel=6"));
    QCOMPARE(combo->currentText(), QStringLiteral("swivel"));
    QVERIFY2(editor->machine(), qPrintable(editor->messageText()));
    // A name used twice is refused with the reason, at the bus cell.
    typeInto(editor->controllersTable()->cell(1, "axes"), QStringLiteral("lift=5 LIFT=6"));
    QVERIFY(!editor->machine());
    QCOMPARE(editor->error().field, QStringLiteral("controllers[1].axes"));
    QVERIFY2(editor->messageText().contains(QStringLiteral("LIFT is given twice")),
             qPrintable(editor->messageText()));
}

void TestMachineEditor::removeAxis_removesTheRowBeingEdited()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    editor->show();
    QVERIFY(QTest::qWaitForWindowActive(editor.get()));
    QWidget* cell = editor->axesTable()->cell(2, "stepsPerUnit");
    cell->setFocus(); // the operator works in Z's row, then presses "Remove axis"
    QTRY_VERIFY(cell->hasFocus());
    QPushButton* remove = nullptr;
    for (QPushButton* b : editor->findChildren<QPushButton*>()) {
        if (b->text() == QStringLiteral("Remove axis"))
            remove = b;
    }
    QVERIFY(remove);
    QTest::mouseClick(remove, Qt::LeftButton);
    const auto machine = editor->machine();
    QVERIFY2(machine, qPrintable(editor->messageText()));
    QCOMPARE(machine->axes.size(), 3);
    QVERIFY(!machine->axis(QStringLiteral("Z")));
    QVERIFY(machine->axis(QStringLiteral("A")));
    QVERIFY(editor->isModified());
}

void TestMachineEditor::removeController_removesTheRowBeingEdited()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    editor->show();
    QVERIFY(QTest::qWaitForWindowActive(editor.get()));
    QWidget* cell = editor->controllersTable()->cell(1, "port");
    cell->setFocus();
    QTRY_VERIFY(cell->hasFocus());
    editor->controllersTable()->removeCurrentController();
    QCOMPARE(editor->controllersTable()->ids(), QStringList{QStringLiteral("table")});
    // Axis A still names the removed controller: the validator says so, at its cell.
    QCOMPARE(editor->error().field, QStringLiteral("axes[3].controller"));
    QCOMPARE(editor->markedCells(), QList<QWidget*>{editor->axesTable()->cell(3, "controller")});
}

void TestMachineEditor::addAxis_takesFreeNameAndControllerAxis()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    editor->axesTable()->selectRow(1); // Y on the table's Y
    editor->axesTable()->removeCurrentAxis();
    editor->axesTable()->addAxis();
    auto machine = editor->machine();
    QVERIFY2(machine, qPrintable(editor->messageText()));
    const machine::MachineAxis& added = machine->axes.last();
    QCOMPARE(added.name, QStringLiteral("Y"));
    QCOMPARE(added.controller, QStringLiteral("table"));
    QCOMPARE(added.axis, Axis::Y);
    QCOMPARE(added.unit, machine::AxisUnit::Step);
    // Every controller axis drives one: the new axis is there, the validator names it.
    editor->axesTable()->addAxis();
    QCOMPARE(editor->axesTable()->rowCount(), 5);
    QCOMPARE(editor->error().field, QStringLiteral("axes[4].axis"));
}

void TestMachineEditor::message_longError_neverReflows()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    editor->resize(editor->sizeHint());
    editor->show();
    QVERIFY(QTest::qWaitForWindowExposed(editor.get()));
    auto* message = editor->findChild<ui::ElidedLabel*>(QStringLiteral("machineMessage"));
    QVERIFY(message);
    const QRect messageBefore = message->geometry();
    const QRect tableBefore = editor->axesTable()->geometry();
    typeInto(editor->controllersTable()->cell(1, "axes"), QString(300, QLatin1Char('x')));
    QVERIFY(editor->messageText().size() > 100);
    QCoreApplication::processEvents();
    QCOMPARE(message->geometry(), messageBefore);
    QCOMPARE(editor->axesTable()->geometry(), tableBefore);
    QVERIFY(message->isElided());
    QCOMPARE(message->toolTipText(), editor->messageText());
}

void TestMachineEditor::sixAxes_fit1366x768()
{
    auto editor = editorWith(QStringLiteral("elab-xyz-nanotec-rotary.machine.json"));
    MachineDescription six = *editor->machine();
    six.controllers[1].busAddresses = {{Axis::X, 1}, {Axis::Y, 2}, {Axis::Z, 3}};
    for (const char* name : {"B", "C"}) {
        machine::MachineAxis a = six.axes.last();
        a.name = QString::fromLatin1(name);
        a.axis = Axis::at(a.axis.index() + 1);
        six.axes << a;
    }
    QVERIFY(MachineFile::validate(six, nullptr));
    editor->setMachine(six);
    QCOMPARE(editor->axesTable()->rowCount(), 6);
    // The screen minus a title bar and a panel: 1366x768 less about 60 pixels of height.
    const QSize hint = editor->sizeHint();
    qInfo("editor size hint with six axes: %dx%d", hint.width(), hint.height());
    QVERIFY2(hint.width() <= 1366 && hint.height() <= 700,
             qPrintable(QStringLiteral("%1x%2").arg(hint.width()).arg(hint.height())));
    editor->resize(hint);
    editor->show();
    QVERIFY(QTest::qWaitForWindowExposed(editor.get()));
    ui::AxesTable* axes = editor->axesTable();
    QVERIFY(axes->horizontalHeader()->length() <= axes->viewport()->width());
    QVERIFY(axes->rowViewportPosition(5) + axes->rowHeight(5) <= axes->viewport()->height());
    QVERIFY(!axes->horizontalScrollBar()->isVisible());
}

STEPDECK_TEST_MAIN(TestMachineEditor)
#include "tst_machineeditor.moc"
