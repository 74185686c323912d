// The check's errors on the Program page (issue 31 finding: the check line named only the
// first error and there was no list): the check line counts them, the list of every error,
// "line N: message", is the preview's last tab (issue 47 item 12: a program with errors that
// leave a path keeps it beside the list, tst_programpage); a program that does not parse has
// no path, and the list is then the one tab, shown where the path was drawn; a click or Enter
// on one puts the editor's cursor at its line and column with the focus; the list follows each
// check; nothing of the page moves.
#include "ProgramPageFixture.h"
#include "TestMain.h"
#include "program/ProgramEditor.h"
#include "program/ProgramErrorList.h"
#include <QListWidget>
#include <QScrollBar>
#include <QTabWidget>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
// Line 3: Q is no word of G0 (at column 4); line 5: B is no axis of the machine (column 4).
const QString kTwoErrors = QStringLiteral("G91\nG0 X1\nG0 Q1 X2\nG0 Y1\nG0 B2\n");
} // namespace

class TestProgramErrors : public ProgramPageFixture
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init()
    {
        QVERIFY(m_rig.start());
        QVERIFY(window()->openMachine(m_rig.writeFile(m_rig.machineJson())));
    }
    void cleanup() { m_rig.stop(); }
    void checkErrors_parseErrors_listAloneWhereThePathWas_namesEach();
    void checkErrors_clickEntry_editorAtThatLine();
    void checkErrors_enterOnEntry_editorAtThatLine();
    void checkErrors_fixed_listFollowsTheCheck();
    void longEntry_wraps_noSidewaysScroll();
    void entryPastTheExcerpt_saysSo();

private:
    ui::ProgramErrorList* list() const { return page()->errorList(); }
    QStringList entries() const
    {
        QStringList texts;
        for (int i = 0; i < list()->list()->count(); ++i)
            texts << list()->list()->item(i)->text();
        return texts;
    }
    // Where a widget of the page stands in the window.
    QRect placeOf(const QWidget* w) const { return QRect(w->mapTo(window(), QPoint()), w->size()); }
    // The editor's cursor: "line:column" (1-based) and the selected text.
    QString cursorPlace() const
    {
        const QTextCursor c = page()->editor()->textCursor();
        return QStringLiteral("%1:%2 '%3'")
            .arg(c.blockNumber() + 1)
            .arg(c.positionInBlock() + 1)
            .arg(c.selectedText());
    }
};

void TestProgramErrors::checkErrors_parseErrors_listAloneWhereThePathWas_namesEach()
{
    setProgram(QStringLiteral("G91\nG0 X1\n"));
    ui::ProgramPreviewView* preview = page()->preview();
    QTabWidget* tabs = preview->tabs();
    const int errorsTab = preview->errorsTabIndex();
    QVERIFY(errorsTab >= 0);
    QVERIFY(preview->isVisible());
    QVERIFY(preview->pathView()->isVisible());
    QVERIFY(!list()->isVisible());           // nothing to list
    QVERIFY(!tabs->isTabEnabled(errorsTab)); // nor to choose
    const QRect place = placeOf(preview);
    const QRect drawing = placeOf(tabs->currentWidget());
    const QRect run = placeOf(page()->controls()->runButton());
    const QRect check = placeOf(page()->findChild<QWidget*>(QStringLiteral("programCheckNow")));
    const QRect editor = placeOf(page()->editor());

    setProgram(kTwoErrors);
    // (Tests load no translation: English plurals read "error(s)".)
    QVERIFY2(page()->checkText().startsWith(QStringLiteral("2 error")) &&
                 page()->checkText().contains(QStringLiteral("line 3: ")),
             qPrintable(page()->checkText()));
    QTRY_VERIFY(list()->isVisible());
    // It does not parse, so it has no path: the list alone, the other tabs not to be chosen.
    QVERIFY(!preview->pathView()->isVisible());
    QVERIFY(!preview->showsErrors());
    QCOMPARE(tabs->currentIndex(), errorsTab);
    for (int i = 0; i < tabs->count(); ++i)
        QCOMPARE(tabs->isTabEnabled(i), i == errorsTab);
    QCOMPARE(tabs->tabText(errorsTab), QStringLiteral("Errors (2)"));
    const QStringList texts = entries();
    QCOMPARE(texts.size(), 2);
    QVERIFY2(texts.at(0).startsWith(QStringLiteral("line 3: ")) &&
                 texts.at(0).contains(QLatin1Char('Q')) &&
                 texts.at(1).startsWith(QStringLiteral("line 5: ")) &&
                 texts.at(1).contains(QLatin1Char('B')),
             qPrintable(texts.join(QLatin1Char('|'))));
    QVERIFY2(list()->headerText().startsWith(QStringLiteral("2 error")),
             qPrintable(list()->headerText()));
    // Exactly where the path was drawn; the preview and the rest of the page did not move.
    QCOMPARE(placeOf(list()), drawing);
    QCOMPARE(placeOf(preview), place);
    QCOMPARE(placeOf(page()->controls()->runButton()), run);
    QCOMPARE(placeOf(page()->findChild<QWidget*>(QStringLiteral("programCheckNow"))), check);
    QCOMPARE(placeOf(page()->editor()), editor);
}

void TestProgramErrors::checkErrors_clickEntry_editorAtThatLine()
{
    setProgram(kTwoErrors);
    QTRY_VERIFY(list()->isVisible());
    QListWidget* entries = list()->list();
    QCOMPARE(entries->count(), 2);
    const QRect second = entries->visualItemRect(entries->item(1));
    QTest::mouseClick(entries->viewport(), Qt::LeftButton, {}, second.center());
    // Line 5 at B's column, the word selected, the editor with the focus.
    QCOMPARE(cursorPlace(), QStringLiteral("5:4 'B2'"));
    QTRY_VERIFY(page()->editor()->hasFocus());
    QVERIFY(list()->isVisible()); // there for the next one
}

void TestProgramErrors::checkErrors_enterOnEntry_editorAtThatLine()
{
    setProgram(kTwoErrors);
    QTRY_VERIFY(list()->isVisible());
    list()->list()->setFocus(); // Tab from the editor's column
    QTRY_VERIFY(list()->list()->hasFocus());
    QCOMPARE(list()->list()->currentRow(), 0);
    QTest::keyClick(list()->list(), Qt::Key_Return);
    QCOMPARE(cursorPlace(), QStringLiteral("3:4 'Q1'"));
    QTRY_VERIFY(page()->editor()->hasFocus());
}

void TestProgramErrors::checkErrors_fixed_listFollowsTheCheck()
{
    setProgram(kTwoErrors);
    QTRY_VERIFY(list()->isVisible());
    QCOMPARE(entries().size(), 2);
    // Line 3 fixed by typing: the debounced check drops its entry.
    QTextCursor c(page()->editor()->document()->findBlockByNumber(2));
    c.select(QTextCursor::LineUnderCursor);
    c.insertText(QStringLiteral("G0 X2"));
    QTRY_COMPARE(entries().size(), 1);
    QVERIFY2(entries().at(0).startsWith(QStringLiteral("line 5: ")), qPrintable(entries().at(0)));
    QTRY_VERIFY(page()->checkText().startsWith(QStringLiteral("1 error")));
    // And the last: the path is back in the list's place, the errors' tab not to be chosen.
    c = QTextCursor(page()->editor()->document()->findBlockByNumber(4));
    c.select(QTextCursor::LineUnderCursor);
    c.insertText(QStringLiteral("G0 Y2"));
    QTRY_VERIFY(entries().isEmpty());
    QTRY_VERIFY(page()->preview()->pathView()->isVisible());
    QVERIFY(!list()->isVisible());
    QVERIFY(!page()->preview()->tabs()->isTabEnabled(page()->preview()->errorsTabIndex()));
}

// A reason longer than the list is wide wraps onto more lines; the list never scrolls sideways.
void TestProgramErrors::longEntry_wraps_noSidewaysScroll()
{
    ui::ProgramEditor editor;
    ui::ProgramErrorList errors(&editor, nullptr);
    errors.resize(240, 300);
    errors.show();
    QVERIFY(QTest::qWaitForWindowExposed(&errors));
    const QString reason = QStringLiteral("X: the position is unknown, so an absolute move "
                                          "could go anywhere: reference the axis first");
    errors.setErrors({{4, 1, reason}, {6, 1, QStringLiteral("B is no axis")}});
    QListWidget* entries = errors.list();
    const int lineHeight = entries->fontMetrics().height();
    QVERIFY(entries->fontMetrics().horizontalAdvance(entries->item(0)->text()) >
            entries->viewport()->width()); // it would not fit on one line
    QTRY_VERIFY2(entries->visualItemRect(entries->item(0)).height() >= 2 * lineHeight,
                 qPrintable(QString::number(entries->visualItemRect(entries->item(0)).height())));
    QVERIFY(entries->visualItemRect(entries->item(0)).width() <= entries->viewport()->width());
    QVERIFY(!entries->horizontalScrollBar()->isVisible());
    QVERIFY(entries->visualItemRect(entries->item(1)).height() < 2 * lineHeight);
}

// A file too large to edit shows its first lines only: an error past them is listed, and a
// click on it says why the editor does not go there (it did nothing, silently).
void TestProgramErrors::entryPastTheExcerpt_saysSo()
{
    ui::ProgramEditor editor;
    editor.setPlainText(QStringLiteral("G0 X1\nG0 X2\nG0 X3"));
    ui::ProgramErrorList errors(&editor, nullptr);
    errors.setErrors({{2, 4, QStringLiteral("bad X")}, {25000, 1, QStringLiteral("B is no axis")}});
    errors.resize(400, 200);
    errors.show();
    QVERIFY(QTest::qWaitForWindowExposed(&errors));
    QListWidget* entries = errors.list();
    QTest::mouseClick(entries->viewport(), Qt::LeftButton, {},
                      entries->visualItemRect(entries->item(1)).center());
    QVERIFY2(errors.headerText().startsWith(QStringLiteral("Line 25000 is not in the editor")) &&
                 errors.headerText().contains(QStringLiteral("first 3 line")),
             qPrintable(errors.headerText()));
    QCOMPARE(editor.textCursor().blockNumber(), 0); // not moved
    QTest::mouseClick(entries->viewport(), Qt::LeftButton, {},
                      entries->visualItemRect(entries->item(0)).center());
    QCOMPARE(editor.textCursor().blockNumber(), 1); // a line it has: there
}

STEPDECK_TEST_MAIN_WITH(TestProgramErrors, runOnLaptopScreen<TestProgramErrors>)
#include "tst_programerrors.moc"
