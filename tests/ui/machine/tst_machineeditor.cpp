// The machine editor (issue 19): a round trip of every shipped example through the editor,
// every typed value validated by MachineFile::validate with the offending cell marked, Save
// refused for an invalid machine, the unsaved-changes question, and the 1366x768 fit.
#include "../UiTestSupport.h"
#include "MachineEditorTestSupport.h"
#include "common/ElidedLabel.h"
#include <QFileDialog>
#include <QHeaderView>
#include <QJsonDocument>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QTemporaryDir>

using namespace stepdeck;
using namespace stepdeck::test;
using machine::MachineDescription;
using machine::MachineFile;
using machine::MachineFileError;
using ui::MachineEditor;

class TestMachineEditor : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void roundTrip_example_savesWhatWasEdited_data();
    void roundTrip_example_savesWhatWasEdited();
    void typedValue_invalid_namesFieldAndMarksCell_data();
    void typedValue_invalid_namesFieldAndMarksCell();
    void typedValue_fixedAgain_clearsMark();
    void save_invalidMachine_isRefused();
    void open_invalidFile_keepsMachineAndNamesField();
    void controllerId_renamed_axesFollow();
    void removeAxis_removesTheRowBeingEdited();
    void removeController_removesTheRowBeingEdited();
    void startFromController_isSingleControllerMachine();
    void close_withUnsavedChanges_asksFirst();
    void message_longError_neverReflows();
    void sixAxes_fit1366x768();

private:
    static std::unique_ptr<MachineEditor> editorWith(const QString& exampleName);
};

std::unique_ptr<MachineEditor> TestMachineEditor::editorWith(const QString& exampleName)
{
    auto editor = std::make_unique<MachineEditor>();
    if (!editor->openFile(example(exampleName)))
        qWarning("%s", qPrintable(editor->messageText()));
    return editor;
}

void TestMachineEditor::roundTrip_example_savesWhatWasEdited_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& file : exampleFiles())
        QTest::newRow(qPrintable(file)) << file;
    QVERIFY(exampleFiles().size() >= 4);
}

void TestMachineEditor::roundTrip_example_savesWhatWasEdited()
{
    QFETCH(QString, file);
    MachineFileError error;
    const std::optional<MachineDescription> loaded = MachineFile::load(example(file), &error);
    QVERIFY2(loaded, qPrintable(error.text()));
    auto editor = editorWith(file);
    QCOMPARE(editor->machine(), loaded); // every cell shows the file's value exactly
    QVERIFY(!editor->isModified());

    MachineDescription expected = *loaded;
    expected.name += QStringLiteral(" 2");
    typeInto(editor->nameEdit(), expected.name);
    for (int i = 0; i < expected.axes.size(); ++i) {
        if (expected.axes[i].unit == machine::AxisUnit::Step)
            continue;
        expected.axes[i].stepsPerUnit = 123.5;
        typeInto(editor->axesTable()->cell(i, "stepsPerUnit"), QStringLiteral("123.5"));
        break;
    }
    QVERIFY(editor->isModified());
    QVERIFY2(editor->error().field.isEmpty(), qPrintable(editor->messageText()));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("edited.machine.json"));
    QSignalSpy saved(editor.get(), &MachineEditor::saved);
    QVERIFY2(editor->saveTo(path), qPrintable(editor->messageText()));
    QCOMPARE(saved.size(), 1);
    QVERIFY(!editor->isModified());
    const std::optional<MachineDescription> readBack = MachineFile::load(path, &error);
    QVERIFY2(readBack, qPrintable(error.text()));
    QCOMPARE(*readBack, expected);
}

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
    QTest::newRow("duplicate name") << "axes" << 1 << "name"
                                    << "X"
                                    << "axes[1].name" << QStringList{"name"};
    QTest::newRow("axis not on bus") << "axes" << 3 << "axis"
                                     << "Y"
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

void TestMachineEditor::save_invalidMachine_isRefused()
{
    auto editor = editorWith(QStringLiteral("nanotec-two-buses.machine.json"));
    typeInto(editor->axesTable()->cell(0, "stepsPerUnit"), QStringLiteral("-2"));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("refused.machine.json"));
    QSignalSpy saved(editor.get(), &MachineEditor::saved);
    QVERIFY(!editor->saveTo(path));
    QVERIFY(!QFile::exists(path));
    QCOMPARE(saved.size(), 0);
    QVERIFY(editor->isModified());
    QVERIFY2(editor->messageText().contains(QStringLiteral("axes[0].stepsPerUnit")),
             qPrintable(editor->messageText()));
    // The Save button refuses it the same way, before any file dialog.
    editor->findChild<QPushButton*>(QStringLiteral("saveButton"))->click();
    QVERIFY(editor->findChildren<QFileDialog*>().isEmpty());
    QVERIFY(editor->messageText().contains(QStringLiteral("axes[0].stepsPerUnit")));
}

void TestMachineEditor::open_invalidFile_keepsMachineAndNamesField()
{
    auto editor = editorWith(QStringLiteral("emis-xyzu.machine.json"));
    const auto before = editor->machine();
    QVERIFY(before);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.machine.json"));
    MachineDescription broken = *before;
    broken.axes[1].stepsPerUnit = -2;
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(broken.toJson()).toJson());
    file.close();
    QVERIFY(!editor->openFile(path));
    QVERIFY2(editor->messageText().contains(QStringLiteral("axes[1].stepsPerUnit")),
             qPrintable(editor->messageText()));
    QCOMPARE(editor->machine(), before);
    QCOMPARE(editor->path(), example(QStringLiteral("emis-xyzu.machine.json")));
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

void TestMachineEditor::startFromController_isSingleControllerMachine()
{
    const ModelInfo* nanotec = findModel(QStringLiteral("nanotec"));
    QVERIFY(nanotec);
    MachineEditor editor(*nanotec, QStringLiteral("/dev/ttyUSB3"));
    QCOMPARE(editor.machine(),
             MachineDescription::singleController(*nanotec, QStringLiteral("/dev/ttyUSB3")));
    QVERIFY(editor.isModified()); // saved nowhere yet
    QVERIFY(editor.path().isEmpty());
    // A reset line is kept for models that have one, left out for the others.
    const ModelInfo* elab = findModel(QStringLiteral("elab"));
    editor.startFromController(*elab, QStringLiteral("sim"), LineSettings::ResetLine::Dtr);
    QCOMPARE(editor.machine()->controllers.first().resetLine, LineSettings::ResetLine::Dtr);
    editor.startFromController(*nanotec, QStringLiteral("sim"), LineSettings::ResetLine::Dtr);
    QVERIFY2(editor.machine(), qPrintable(editor.messageText()));
    QCOMPARE(editor.machine()->controllers.first().resetLine, std::nullopt);
}

void TestMachineEditor::close_withUnsavedChanges_asksFirst()
{
    auto editor = editorWith(QStringLiteral("laser-axes.machine.json"));
    editor->show();
    typeInto(editor->nameEdit(), QStringLiteral("Changed"));
    QVERIFY(!editor->close());
    QVERIFY(editor->isVisible());
    QMessageBox* prompt = editor->pendingPrompt();
    QVERIFY(prompt);
    QVERIFY(!prompt->isModal());
    QVERIFY(!editor->close()); // asked once, not twice
    QCOMPARE(editor->pendingPrompt(), prompt);
    prompt->button(QMessageBox::Cancel)->click();
    QVERIFY(editor->isVisible());
    QVERIFY(editor->isModified());
    QVERIFY(!editor->close());
    QVERIFY(editor->pendingPrompt());
    editor->pendingPrompt()->button(QMessageBox::Discard)->click();
    QVERIFY(!editor->isVisible());
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
        a.axis = Axis(int(a.axis) + 1);
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

QTEST_MAIN(TestMachineEditor)
#include "tst_machineeditor.moc"
