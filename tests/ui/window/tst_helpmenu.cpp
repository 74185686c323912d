// Issue 31 (a finding): the Help menu had only About. It now lists the keyboard shortcuts, read
// from the window's own actions (STOP and PANIC first, the keyboard jog's keys with the axes
// they move), and the command line's usage; each opens non-modal.
#include "../UiTestSupport.h"
#include "jog/JogPanel.h"
#include "window/HelpMenu.h"
#include "window/ShortcutsDialog.h"
#include <QAction>
#include <QApplication>
#include <QPlainTextEdit>
#include <QTableWidget>
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

QTEST_MAIN(TestHelpMenu)
#include "tst_helpmenu.moc"
