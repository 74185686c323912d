// The input-program editor on an EMIS SMC-IC4 (in-process simulator, offscreen): the eight
// inputs, commands checked while typing (nothing is sent while one is invalid), writing and
// erasing as the board sees it, and the deliberate override for reference-switch inputs.
#include "EmisUiFixture.h"
#include "TestMain.h"
#include "programs/InputProgramsPage.h"
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestInputProgramsPage : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup();
    void list_eightInputs_referenceSwitchesDescribed();
    void invalidCommand_namedAndNothingSent();
    void write_boardStoresProgram_listSaysWritten();
    void referenceInput_refused_thenWrittenAnyway();
    void erase_boardForgetsProgram();
    void drafts_keptPerInput();

private:
    ui::InputProgramsPage* page() const { return m_f->window->inputProgramsPage(); }
    std::optional<emis::EmisSimulator::InputProgram> boardProgram(int input);
    std::unique_ptr<EmisUiFixture> m_f;
};

void TestInputProgramsPage::init()
{
    QSettings().clear();
    m_f = std::make_unique<EmisUiFixture>();
    QVERIFY(m_f->connectEmis());
}

void TestInputProgramsPage::cleanup()
{
    m_f.reset();
}

std::optional<emis::EmisSimulator::InputProgram> TestInputProgramsPage::boardProgram(int input)
{
    std::optional<emis::EmisSimulator::InputProgram> out;
    m_f->withEmis([&](emis::EmisSimulator* s) { out = s->program(input); });
    return out;
}

void TestInputProgramsPage::list_eightInputs_referenceSwitchesDescribed()
{
    QCOMPARE(page()->inputList()->count(), 8);
    QVERIFY(page()->inputList()->item(0)->toolTip().contains("reference switch of axis X"));
    QVERIFY(page()->inputList()->item(6)->toolTip().contains("free input"));
    QVERIFY(page()->inputList()->item(6)->text().contains("not written from here"));
}

void TestInputProgramsPage::invalidCommand_namedAndNothingSent()
{
    page()->selectInput(6);
    page()->titleEdit()->setText("t");
    page()->commandsEdit()->setPlainText("L1,x10\nFOO\nW700000");
    QVERIFY(page()->checkText().contains("Line 2"));
    QVERIFY(page()->checkText().contains("Line 3"));
    QVERIFY(!page()->writeButton()->isEnabled());
    QVERIFY(!page()->writeProgram());
    page()->commandsEdit()->setPlainText("@IG");
    QVERIFY(!page()->writeButton()->isEnabled()); // a query is no program command
    for (const QByteArray& c : m_f->boardCommands())
        QVERIFY(!c.startsWith("*PWIN"));
}

void TestInputProgramsPage::write_boardStoresProgram_listSaysWritten()
{
    page()->selectInput(8);
    page()->titleEdit()->setText("Eingang 8: Vektorfahrt X-Motor");
    page()->commandsEdit()->setPlainText("L1,x191\n\nW1500\n");
    QVERIFY(page()->checkText().contains("valid"));
    QVERIFY(page()->writeButton()->isEnabled());
    page()->writeButton()->click();
    QTRY_VERIFY(page()->messageText().contains("stored"));
    const auto program = boardProgram(8);
    QVERIFY(program.has_value());
    QCOMPARE(program->title, QByteArray("Eingang 8: Vektorfahrt X-Motor"));
    QCOMPARE(program->commands, (QList<QByteArray>{"L1,x191", "W1500"}));
    QVERIFY(page()->inputList()->item(7)->text().contains("written"));
}

void TestInputProgramsPage::referenceInput_refused_thenWrittenAnyway()
{
    page()->selectInput(2);
    page()->titleEdit()->setText("t");
    page()->commandsEdit()->setPlainText("A1,1");
    QVERIFY(page()->writeProgram());
    QTRY_VERIFY(page()->messageText().contains("5.2.2"));
    QVERIFY(page()->forceButton()->isVisibleTo(page()));
    QVERIFY(!boardProgram(2).has_value());
    page()->forceButton()->click();
    QTRY_VERIFY(page()->messageText().contains("stored"));
    QVERIFY(boardProgram(2).has_value());
}

void TestInputProgramsPage::erase_boardForgetsProgram()
{
    page()->selectInput(5);
    page()->titleEdit()->setText("x");
    page()->commandsEdit()->setPlainText("W10");
    QVERIFY(page()->writeProgram());
    QTRY_VERIFY(boardProgram(5).has_value());
    QTRY_VERIFY(page()->eraseButton()->isEnabled());
    page()->eraseButton()->click();
    QTRY_VERIFY(page()->messageText().contains("erased"));
    QVERIFY(!boardProgram(5).has_value());
    QVERIFY(page()->inputList()->item(4)->text().contains("erased"));
}

void TestInputProgramsPage::drafts_keptPerInput()
{
    page()->selectInput(7);
    page()->titleEdit()->setText("seven");
    QTest::keyClicks(page()->titleEdit(), "!"); // typed: saved as a draft
    page()->commandsEdit()->setPlainText("W7");
    page()->selectInput(6);
    QVERIFY(page()->titleEdit()->text().isEmpty());
    page()->selectInput(7);
    QCOMPARE(page()->titleEdit()->text(), QStringLiteral("seven!"));
    QCOMPARE(page()->commandsEdit()->toPlainText(), QStringLiteral("W7"));
}

STEPDECK_TEST_MAIN(TestInputProgramsPage)
#include "tst_inputprogramspage.moc"
