// The window's Help menu (HelpMenu.h).
#include "HelpMenu.h"
#include "DocumentationDialog.h"
#include "ShortcutsDialog.h"
#include "common/Dialogs.h"
#include "jog/JogPanel.h"
#include <QApplication>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace stepdeck::ui {

HelpMenu::HelpMenu(QWidget* window, JogPanel* jog, QWidget* parent)
    : QMenu(tr("&Help"), parent), m_window(window), m_jog(jog)
{
    // Not on F1: F1 is PANIC.
    m_documentation = addAction(tr("&Documentation\u2026"), this, [this] {
        dialogs::showForPart(new DocumentationDialog(m_window), m_window);
    });
    m_shortcuts = addAction(tr("&Keyboard shortcuts\u2026"), this, &HelpMenu::showShortcuts);
    m_commandLine = addAction(tr("&Command line\u2026"), this, &HelpMenu::showCommandLine);
    m_commandLine->setVisible(false);
    addSeparator();
    addAction(tr("&About StepDeck"), this, [this] {
        dialogs::message(m_window, QMessageBox::Information, tr("About StepDeck"),
                         tr("<b>StepDeck</b> %1<br>Operator and technician software for "
                            "stepper-motor controllers.<br><br>Esc: ramped stop of all "
                            "motion<br>F1: panic stop (positions are lost)")
                             .arg(QApplication::applicationVersion()));
    });
    // QApplication::aboutQt() is modal: the same facts in a non-modal box.
    addAction(tr("About &Qt"), this, [this] {
        dialogs::message(m_window, QMessageBox::Information, tr("About Qt"),
                         tr("StepDeck uses Qt %1, a cross-platform application framework "
                            "by The Qt Company, under the GNU LGPL version 3. See "
                            "<a href=\"https://www.qt.io/\">qt.io</a>.")
                             .arg(QString::fromLatin1(qVersion())));
    });
}

void HelpMenu::setCommandLineHelp(const QString& text)
{
    m_commandLineHelp = text;
    m_commandLine->setVisible(!text.isEmpty());
}

void HelpMenu::showShortcuts()
{
    auto* dialog =
        new ShortcutsDialog(m_window, m_jog ? m_jog->keyboardLegend() : QString(), m_window);
    dialogs::showForPart(dialog, m_window);
}

void HelpMenu::showCommandLine()
{
    auto* dialog = new QDialog(m_window);
    dialog->setObjectName(QStringLiteral("commandLineHelp"));
    dialog->setWindowTitle(tr("Command line: stepdeck-cli"));
    auto* text = new QPlainTextEdit(m_commandLineHelp, dialog);
    text->setReadOnly(true);
    text->setLineWrapMode(QPlainTextEdit::NoWrap);
    text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(text, 1);
    layout->addWidget(buttons);
    dialog->resize(760, 520);
    dialogs::showForPart(dialog, m_window);
}

} // namespace stepdeck::ui
