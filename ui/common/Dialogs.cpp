#include "Dialogs.h"
#include <QDialog>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QPointer>
#include <QSettings>
#include <QStandardPaths>

namespace stepdeck::ui::dialogs {

namespace {
const char* const kOpenDialogs = "stepdeckOpenDialogs";

const QString kAnyFolder = QStringLiteral("dialogs/lastFolder");

QString folderKey(const QString& key)
{
    return QStringLiteral("dialogs/%1/folder").arg(key);
}

QString existingFolder(const QString& settingsKey)
{
    const QString stored = QSettings().value(settingsKey).toString();
    return !stored.isEmpty() && QDir(stored).exists() ? stored : QString();
}

QFileDialog* fileDialog(QWidget* part, const QString& key, const QString& title,
                        const QString& filter, std::function<void(const QString&)> done)
{
    auto* dialog = new QFileDialog(part->window(), title, lastFolder(key), filter);
    // Native dialogs run their own modal loop and swallow Esc and F1.
    dialog->setOption(QFileDialog::DontUseNativeDialog, true);
    QObject::connect(dialog, &QFileDialog::fileSelected, dialog,
                     [key, done = std::move(done)](const QString& path) {
                         if (path.isEmpty())
                             return;
                         rememberFolder(key, QFileInfo(path).absolutePath());
                         if (done)
                             done(path);
                     });
    return dialog;
}
} // namespace

void showForPart(QDialog* dialog, QWidget* part)
{
    dialog->setWindowModality(Qt::NonModal);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    if (part && !part->isWindow()) { // a whole window holds the safety bar: never disabled
        // Several dialogs of one page: the page is enabled again when the last one closes.
        part->setProperty(kOpenDialogs, part->property(kOpenDialogs).toInt() + 1);
        part->setEnabled(false);
        QPointer<QWidget> guard(part);
        QObject::connect(dialog, &QDialog::finished, part, [guard] {
            if (!guard)
                return;
            const int open = qMax(0, guard->property(kOpenDialogs).toInt() - 1);
            guard->setProperty(kOpenDialogs, open);
            if (open == 0)
                guard->setEnabled(true);
        });
    }
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

QString lastFolder(const QString& key)
{
    QString folder = existingFolder(folderKey(key));
    if (folder.isEmpty())
        folder = existingFolder(kAnyFolder); // a dialog used for the first time
    if (folder.isEmpty())
        folder = defaultFolder();
    return folder;
}

QString defaultFolder()
{
    // Documents need not exist (a fresh account, a machine set up without a desktop): the
    // dialog would open somewhere else and a save there fail. Create it; where that is not
    // allowed, the home folder, and as a last resort the temporary one.
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (!documents.isEmpty() && QDir().mkpath(documents) && QFileInfo(documents).isWritable())
        return documents;
    const QFileInfo home(QDir::homePath());
    if (home.isDir() && home.isWritable())
        return home.absoluteFilePath();
    return QDir::tempPath();
}

void rememberFolder(const QString& key, const QString& folder)
{
    QSettings settings;
    settings.setValue(folderKey(key), folder);
    settings.setValue(kAnyFolder, folder);
}

QFileDialog* saveFile(QWidget* part, const QString& key, const QString& title,
                      const QString& defaultName, const QString& filter,
                      std::function<void(const QString&)> done)
{
    QFileDialog* dialog = fileDialog(part, key, title, filter, std::move(done));
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setFileMode(QFileDialog::AnyFile);
    dialog->selectFile(QDir(lastFolder(key)).filePath(defaultName));
    showForPart(dialog, part);
    return dialog;
}

QFileDialog* openFile(QWidget* part, const QString& key, const QString& title,
                      const QString& filter, std::function<void(const QString&)> done)
{
    QFileDialog* dialog = fileDialog(part, key, title, filter, std::move(done));
    dialog->setAcceptMode(QFileDialog::AcceptOpen);
    dialog->setFileMode(QFileDialog::ExistingFile);
    showForPart(dialog, part);
    return dialog;
}

QMessageBox* message(QWidget* part, QMessageBox::Icon icon, const QString& title,
                     const QString& text, QMessageBox::StandardButtons buttons,
                     QMessageBox::StandardButton defaultButton,
                     std::function<void(QMessageBox::StandardButton)> done)
{
    QWidget* parent = part ? part->window() : nullptr;
    auto* box = new QMessageBox(icon, title, text, buttons, parent);
    if (defaultButton != QMessageBox::NoButton)
        box->setDefaultButton(defaultButton);
    if (done) {
        QObject::connect(box, &QMessageBox::finished, box, [box, done = std::move(done)] {
            QAbstractButton* clicked = box->clickedButton();
            done(clicked ? box->standardButton(clicked) : QMessageBox::NoButton);
        });
    }
    showForPart(box, part);
    return box;
}

} // namespace stepdeck::ui::dialogs
