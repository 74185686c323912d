// The machine editor's files (issue 19): a round trip of every shipped example through the
// editor, Save refused for an invalid machine, a file with a wrong value opened marked (one with
// a broken structure not opened), a new machine from
// the connected controller, and the unsaved-changes question.
#include "../UiTestSupport.h"
#include "MachineEditorTestSupport.h"
#include "TestMain.h"
#include <QFileDialog>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>

using namespace stepdeck;
using namespace stepdeck::test;
using machine::MachineDescription;
using machine::MachineFile;
using machine::MachineFileError;
using ui::MachineEditor;

namespace {
bool writeJson(const QString& path, const QJsonObject& json)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(QJsonDocument(json).toJson()) > 0;
}
} // namespace

class TestMachineEditorFiles : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void roundTrip_example_savesWhatWasEdited_data();
    void roundTrip_example_savesWhatWasEdited();
    void save_invalidMachine_isRefused();
    void open_invalidValue_opensMarkedAndCanBeFixed();
    void open_brokenStructure_keepsMachineAndNamesField();
    void startFromController_isSingleControllerMachine();
    void close_withUnsavedChanges_asksFirst();
};

void TestMachineEditorFiles::roundTrip_example_savesWhatWasEdited_data()
{
    QTest::addColumn<QString>("file");
    for (const QString& file : exampleFiles())
        QTest::newRow(qPrintable(file)) << file;
    QVERIFY(exampleFiles().size() >= 4);
}

void TestMachineEditorFiles::roundTrip_example_savesWhatWasEdited()
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
    // A setup file the example names beside it goes beside the copy too.
    for (const machine::MachineController& c : loaded->controllers)
        if (!c.setupFile.isEmpty())
            QVERIFY(QFile::copy(example(c.setupFile), dir.filePath(c.setupFile)));
    QSignalSpy saved(editor.get(), &MachineEditor::saved);
    QVERIFY2(editor->saveTo(path), qPrintable(editor->messageText()));
    QCOMPARE(saved.size(), 1);
    QVERIFY(!editor->isModified());
    const std::optional<MachineDescription> readBack = MachineFile::load(path, &error);
    QVERIFY2(readBack, qPrintable(error.text()));
    QCOMPARE(*readBack, expected);
}

void TestMachineEditorFiles::save_invalidMachine_isRefused()
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

// A file whose value breaks a rule opens with the field marked, so that it can be fixed and
// saved here; a file whose structure does not read (an unknown key) leaves the editor as it was.
void TestMachineEditorFiles::open_invalidValue_opensMarkedAndCanBeFixed()
{
    auto editor = editorWith(QStringLiteral("emis-xyzu.machine.json"));
    const auto before = editor->machine();
    QVERIFY(before);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.machine.json"));
    MachineDescription broken = *before;
    broken.axes[1].stepsPerUnit = -2;
    QVERIFY(writeJson(path, broken.toJson()));
    QVERIFY(editor->openFile(path));
    QCOMPARE(editor->path(), path);
    QCOMPARE(editor->error().field, QStringLiteral("axes[1].stepsPerUnit"));
    QVERIFY2(editor->messageText().contains(QStringLiteral("axes[1].stepsPerUnit")),
             qPrintable(editor->messageText()));
    QCOMPARE(editor->markedCells(), editor->cellsOf(QStringLiteral("axes[1].stepsPerUnit")));
    QVERIFY(!editor->machine()); // invalid as it stands
    typeInto(editor->axesTable()->cell(1, "stepsPerUnit"),
             QString::number(before->axes[1].stepsPerUnit));
    QVERIFY2(editor->error().field.isEmpty(), qPrintable(editor->messageText()));
    QVERIFY(editor->saveTo(path));
    MachineFileError error;
    QCOMPARE(MachineFile::load(path, &error), before);
}

void TestMachineEditorFiles::open_brokenStructure_keepsMachineAndNamesField()
{
    auto editor = editorWith(QStringLiteral("emis-xyzu.machine.json"));
    const auto before = editor->machine();
    QVERIFY(before);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.machine.json"));
    QJsonObject json = before->toJson();
    QJsonArray axes = json.value(QStringLiteral("axes")).toArray();
    QJsonObject axis = axes.at(1).toObject();
    axis.insert(QStringLiteral("stepsPerMm"), 400); // not a key of the format
    axes.replace(1, axis);
    json.insert(QStringLiteral("axes"), axes);
    QVERIFY(writeJson(path, json));
    QVERIFY(!editor->openFile(path));
    QVERIFY2(editor->messageText().contains(QStringLiteral("axes[1]")),
             qPrintable(editor->messageText()));
    QCOMPARE(editor->machine(), before);
    QCOMPARE(editor->path(), example(QStringLiteral("emis-xyzu.machine.json")));
}

void TestMachineEditorFiles::startFromController_isSingleControllerMachine()
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

void TestMachineEditorFiles::close_withUnsavedChanges_asksFirst()
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

STEPDECK_TEST_MAIN(TestMachineEditorFiles)
#include "tst_machineeditorfiles.moc"
