// Issue 31 (a finding): the Help menu had only About. It now lists the keyboard shortcuts, read
// from the window's own actions (STOP and PANIC first, the keyboard jog's keys with the axes
// they move), and the command line's usage; each opens non-modal.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "jog/JogPanel.h"
#include "window/DocumentationDialog.h"
#include "window/HelpMenu.h"
#include "window/ShortcutsDialog.h"
#include <QAction>
#include <QApplication>
#include <QImage>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QtTest>

using namespace stepdeck;
using namespace stepdeck::test;

class TestHelpMenu : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void shortcuts_fromTheWindowsActions_safetyFirstJogKeysListed();
    void shortcuts_action_opensNonModalTableOfThem();
    void commandLine_hiddenWithoutText_showsTheUsageGiven();
    void documentation_action_opensEveryDocumentWithItsImages();
};

namespace {
QStringList keys(const QList<QPair<QString, QString>>& rows)
{
    QStringList out;
    for (const auto& r : rows)
        out << r.first;
    return out;
}
} // namespace

void TestHelpMenu::shortcuts_fromTheWindowsActions_safetyFirstJogKeysListed()
{
    UiFixture f;
    const QString legend = f.window->jogPanel()->keyboardLegend();
    QVERIFY(!legend.isEmpty());
    const QList<QPair<QString, QString>> rows = ui::ShortcutsDialog::rows(f.window.get(), legend);
    const QString esc = QKeySequence(Qt::Key_Escape).toString(QKeySequence::NativeText);
    const QString f1 = QKeySequence(Qt::Key_F1).toString(QKeySequence::NativeText);
    // STOP and PANIC work wherever the focus is: listed first.
    QCOMPARE(QSet<QString>({rows.at(0).first, rows.at(1).first}), QSet<QString>({esc, f1}));
    const QString reference = QKeySequence(Qt::CTRL | Qt::Key_H).toString(QKeySequence::NativeText);
    const QStringList listed = keys(rows);
    QVERIFY2(listed.contains(reference), qPrintable(listed.join(QStringLiteral(" | "))));
    QCOMPARE(rows.last().first, legend);
    // Every shortcut once.
    QCOMPARE(QSet<QString>(listed.cbegin(), listed.cend()).size(), rows.size());
    for (const auto& r : rows)
        QVERIFY2(!r.second.contains(QLatin1Char('&')), qPrintable(r.second));
}

void TestHelpMenu::shortcuts_action_opensNonModalTableOfThem()
{
    UiFixture f;
    f.window->show();
    QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
    f.window->helpMenu()->shortcutsAction()->trigger();
    ui::ShortcutsDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = f.window->findChild<ui::ShortcutsDialog*>()));
    QTRY_VERIFY(dialog->isVisible());
    QCOMPARE(dialog->windowModality(), Qt::NonModal);
    const auto* table = dialog->findChild<QTableWidget*>(QStringLiteral("shortcutsTable"));
    QVERIFY(table);
    const auto rows =
        ui::ShortcutsDialog::rows(f.window.get(), f.window->jogPanel()->keyboardLegend());
    QCOMPARE(table->rowCount(), int(rows.size()));
    QCOMPARE(table->item(0, 0)->text(), rows.first().first);
    dialog->close();
}

void TestHelpMenu::commandLine_hiddenWithoutText_showsTheUsageGiven()
{
    UiFixture f;
    f.window->show();
    QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
    ui::HelpMenu* help = f.window->helpMenu();
    QVERIFY(!help->commandLineAction()->isVisible()); // the ui library alone has no CLI text
    help->setCommandLineHelp(QStringLiteral("Usage: stepdeck-cli COMMAND"));
    QVERIFY(help->commandLineAction()->isVisible());
    help->commandLineAction()->trigger();
    QDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = f.window->findChild<QDialog*>(QStringLiteral("commandLineHelp"))));
    QCOMPARE(dialog->windowModality(), Qt::NonModal);
    QCOMPARE(dialog->findChild<QPlainTextEdit*>()->toPlainText(),
             QStringLiteral("Usage: stepdeck-cli COMMAND"));
    dialog->close();
}

// The operator's documents are in the program (an installed StepDeck has no source tree): each
// opens with its text, and the README's screenshot is found next to it.
void TestHelpMenu::documentation_action_opensEveryDocumentWithItsImages()
{
    UiFixture f;
    f.window->show();
    QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
    f.window->helpMenu()->documentationAction()->trigger();
    ui::DocumentationDialog* dialog = nullptr;
    QTRY_VERIFY((dialog = f.window->findChild<ui::DocumentationDialog*>()));
    QTRY_VERIFY(dialog->isVisible());
    QCOMPARE(dialog->windowModality(), Qt::NonModal);
    const QList<ui::DocumentationDialog::Document> docs = ui::DocumentationDialog::documents();
    QCOMPARE(dialog->list()->count(), int(docs.size()));
    const QStringList expected{QStringLiteral("tools/run"), QStringLiteral("stepsPerUnit"),
                               QStringLiteral("G54"), QStringLiteral("stepdeck-cli")};
    for (int i = 0; i < docs.size(); ++i) {
        dialog->list()->setCurrentRow(i);
        QCOMPARE(dialog->browser()->source(), docs.at(i).source);
        const QString text = dialog->browser()->toPlainText();
        QVERIFY2(text.size() > 2000 && text.contains(expected.at(i)),
                 qPrintable(docs.at(i).title + QStringLiteral(": ") + text.left(200)));
        QVERIFY2(!text.contains(QStringLiteral("](")), qPrintable(docs.at(i).title)); // rendered
    }
    dialog->list()->setCurrentRow(0);
    const QVariant image = dialog->browser()->loadResource(
        QTextDocument::ImageResource, QUrl(QStringLiteral("docs/screenshots/run-1366x768.png")));
    QVERIFY(!QImage::fromData(image.toByteArray()).isNull());
    // Shown no wider than the page (the screenshot is 1366 px wide).
    int images = 0;
    const int page = dialog->browser()->viewport()->width();
    for (QTextBlock b = dialog->browser()->document()->begin(); b.isValid(); b = b.next()) {
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextImageFormat format = it.fragment().charFormat().toImageFormat();
            if (!format.isValid())
                continue;
            ++images;
            QVERIFY2(format.width() > 0 && format.width() <= page,
                     qPrintable(QStringLiteral("%1 in %2").arg(format.width()).arg(page)));
        }
    }
    QVERIFY(images >= 1);
    // Narrower, then wide again: the screenshot takes the room back.
    const auto firstImageWidth = [dialog] {
        for (QTextBlock b = dialog->browser()->document()->begin(); b.isValid(); b = b.next()) {
            for (auto it = b.begin(); !it.atEnd(); ++it) {
                const QTextImageFormat format = it.fragment().charFormat().toImageFormat();
                if (format.isValid())
                    return format.width();
            }
        }
        return 0.0;
    };
    const double wide = firstImageWidth();
    dialog->resize(dialog->width() / 2, dialog->height());
    QTRY_VERIFY(firstImageWidth() < wide);
    dialog->resize(dialog->width() * 2, dialog->height());
    QTRY_COMPARE(firstImageWidth(), wide);
    dialog->close();
}

STEPDECK_TEST_MAIN(TestHelpMenu)
#include "tst_helpmenu.moc"
