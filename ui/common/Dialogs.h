#pragma once
#include <QMessageBox>
#include <functional>

class QDialog;
class QFileDialog;
class QWidget;

namespace stepdeck::ui::dialogs {

// Every StepDeck dialog is non-modal (issue 7, rule 5): a modal dialog blocks the window's
// STOP and PANIC buttons, and a native file dialog swallows Esc and F1, while a move may be
// running. What modality would protect is protected by disabling `part` -- the page the
// dialog belongs to, never the safety bar -- while the dialog is open. The dialog is
// parented to part's window (it stays on top of it) and deleted when closed.
// tst_dialogpolicy rejects exec(), the static QFileDialog/QMessageBox/QInputDialog helpers
// and native file dialogs anywhere under ui/: use these functions instead.

// Shows dialog non-modal; part is disabled until it closes (unless part is a whole window:
// that would disable the safety bar).
void showForPart(QDialog* dialog, QWidget* part);

// A non-native, non-modal file dialog. done(path) runs when a file was chosen (not on
// cancel). Every file dialog goes through these (issue 11: they remember the last folder):
// the folder is remembered per key (QSettings "dialogs/<key>/folder"); a key used for the
// first time starts in the folder any file dialog used last, else in defaultFolder().
QFileDialog* saveFile(QWidget* part, const QString& key, const QString& title,
                      const QString& defaultName, const QString& filter,
                      std::function<void(const QString&)> done);
QFileDialog* openFile(QWidget* part, const QString& key, const QString& title,
                      const QString& filter, std::function<void(const QString&)> done);
QString lastFolder(const QString& key);
// Where a dialog starts without a remembered folder: Documents, created if missing (issue 16);
// the home folder where that cannot be done; else the temporary folder. Always exists.
QString defaultFolder();
void rememberFolder(const QString& key, const QString& folder);

// A non-modal message box; done(button) runs with the button chosen (Esc: the escape
// button, or NoButton).
QMessageBox* message(QWidget* part, QMessageBox::Icon icon, const QString& title,
                     const QString& text, QMessageBox::StandardButtons buttons = QMessageBox::Ok,
                     QMessageBox::StandardButton defaultButton = QMessageBox::NoButton,
                     std::function<void(QMessageBox::StandardButton)> done = {});

} // namespace stepdeck::ui::dialogs
