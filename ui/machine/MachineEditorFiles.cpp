// MachineEditor: opening, saving and the unsaved-changes question.
#include "MachineEditor.h"
#include "common/Dialogs.h"
#include <QCloseEvent>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>

namespace stepdeck::ui {

using machine::MachineDescription;
using machine::MachineFile;
using machine::MachineFileError;

namespace {
const QString kFolderKey = QStringLiteral("machines");

QString fileFilter()
{
    return MachineEditor::tr("StepDeck machines (*.machine.json);;JSON files (*.json)");
}

// "Engraving table" -> "Engraving-table.machine.json"
QString defaultFileName(const QString& machineName)
{
    QString stem = machineName.trimmed();
    stem.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("-"));
    return (stem.isEmpty() ? QStringLiteral("machine") : stem) + QStringLiteral(".machine.json");
}
} // namespace

// A file whose values break a rule opens all the same, its first error shown and marked
// (MachineFile::loadDraft): the editor is where such a file gets fixed. Only a file whose
// structure does not read (JSON, keys, types) stays closed.
bool MachineEditor::openFile(const QString& path)
{
    MachineFileError error;
    const std::optional<MachineDescription> loaded = MachineFile::loadDraft(path, &error);
    if (!loaded) {
        showMessage(tr("Not opened: %1: %2").arg(QFileInfo(path).fileName(), error.text()), true);
        return false;
    }
    setMachine(*loaded, path);
    return true;
}

bool MachineEditor::saveTo(const QString& path)
{
    MachineDescription d;
    MachineFileError error;
    if (!readMachine(&d, &error)) {
        showMessage(tr("Not saved: %1").arg(error.text()), true);
        return false;
    }
    QString failure;
    if (!MachineFile::save(d, path, &failure)) {
        showMessage(tr("Not saved: %1").arg(failure), true);
        return false;
    }
    m_path = path;
    setModified(false);
    showMessage(tr("Saved to %1").arg(path), false);
    m_reopen->hide(); // offered again by whoever knows this file is the machine open now
    Q_EMIT saved(path);
    return true;
}

void MachineEditor::save()
{
    if (m_path.isEmpty())
        saveAs();
    else
        saveTo(m_path);
}

void MachineEditor::saveAs()
{
    saveAsThen({});
}

void MachineEditor::saveAsThen(std::function<void()> next)
{
    // Refused before the file dialog: the operator sees why at once.
    MachineDescription d;
    MachineFileError error;
    if (!readMachine(&d, &error)) {
        showMessage(tr("Not saved: %1").arg(error.text()), true);
        return;
    }
    dialogs::saveFile(this, kFolderKey, tr("Save machine"), defaultFileName(d.name), fileFilter(),
                      [this, next = std::move(next)](const QString& path) {
                          if (saveTo(path) && next)
                              next();
                      });
}

void MachineEditor::chooseFile()
{
    afterUnsavedChanges([this] {
        dialogs::openFile(this, kFolderKey, tr("Open machine"), fileFilter(),
                          [this](const QString& path) { openFile(path); });
    });
}

void MachineEditor::afterUnsavedChanges(std::function<void()> next)
{
    if (!m_modified) {
        next();
        return;
    }
    if (m_prompt) { // asked already: the open question stays the one to answer
        m_prompt->raise();
        return;
    }
    const QString name = m_name->text().trimmed();
    m_prompt = dialogs::message(this, QMessageBox::Question, tr("Unsaved changes"),
                                tr("The machine \"%1\" has unsaved changes. Save them?").arg(name),
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                QMessageBox::Save,
                                [this, next = std::move(next)](QMessageBox::StandardButton button) {
                                    if (button == QMessageBox::Discard) {
                                        next();
                                    } else if (button == QMessageBox::Save) {
                                        if (m_path.isEmpty())
                                            saveAsThen(next);
                                        else if (saveTo(m_path))
                                            next();
                                    }
                                });
}

void MachineEditor::closeThen(std::function<void()> next)
{
    afterUnsavedChanges([this, next = std::move(next)] {
        m_closing = true;
        close();
        m_closing = false;
        next();
    });
}

void MachineEditor::closeEvent(QCloseEvent* event)
{
    if (m_closing || !m_modified) {
        event->accept();
        return;
    }
    event->ignore();
    afterUnsavedChanges([this] {
        m_closing = true;
        close();
        m_closing = false; // a window kept after closing asks again next time
    });
}

} // namespace stepdeck::ui
