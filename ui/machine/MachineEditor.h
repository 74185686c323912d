#pragma once
#include "machine/MachineFile.h"
#include <QMessageBox>
#include <QPointer>
#include <QWidget>
#include <functional>

class QCheckBox;
class QHBoxLayout;
class QLineEdit;
class QPushButton;

namespace stepdeck::ui {

class AxesTable;
class ControllersTable;
class ElidedLabel;

// The machine editor (issue 19): a window of its own, never modal, that edits a
// MachineDescription -- its name and spindle scale, the controllers table and the axes table. Every
// edit is validated as typed with MachineFile::validate (the CLI's validator): the first error is
// shown in a one-line message that never re-flows the layout, and its field's cell is marked.
// Save refuses an invalid machine; closing with unsaved changes asks first.
class MachineEditor : public QWidget
{
    Q_OBJECT
public:
    // An empty new machine (one simulated controller of the first model, no axes yet).
    explicit MachineEditor(QWidget* parent = nullptr);
    // A new machine of the controller connected now: MachineDescription::singleController,
    // with the reset line it is connected with (models that have one).
    MachineEditor(const ModelInfo& model, const QString& port,
                  std::optional<LineSettings::ResetLine> resetLine = std::nullopt,
                  QWidget* parent = nullptr);

    void setMachine(const machine::MachineDescription& machine, const QString& path = {});
    // A new machine (not saved anywhere yet) that starts as `machine`: the connection bar's
    // machine of one controller, to be saved as a file of its own.
    void startFrom(const machine::MachineDescription& machine);
    void startFromController(const ModelInfo& model, const QString& port,
                             std::optional<LineSettings::ResetLine> resetLine = std::nullopt);
    // Loads a machine file into the editor; false (and the reason shown) when it is not one.
    bool openFile(const QString& path);
    // Writes the machine (MachineDescription::toJson) to path; refused while it is invalid.
    bool saveTo(const QString& path);
    // Closes the editor -- after the unsaved-changes question when there are any -- and then
    // runs next; Cancel leaves the editor open and next is never run.
    void closeThen(std::function<void()> next);

    // The machine as edited when it is valid.
    std::optional<machine::MachineDescription> machine() const;
    QString path() const { return m_path; }
    bool isModified() const { return m_modified; }
    // The first error (empty field and message: valid), the message line's full text and the
    // widgets marked for it.
    const machine::MachineFileError& error() const { return m_error; }
    QString messageText() const;
    QList<QWidget*> markedCells() const;
    // The widgets of a field as the validator names it ("axes[3].stepsPerUnit").
    QList<QWidget*> cellsOf(const QString& field) const;

    QLineEdit* nameEdit() const { return m_name; }
    QLineEdit* maxRpmEdit() const { return m_maxRpm; } // spindle.maxRpm; empty: none
    QCheckBox* m_crossFeed = nullptr;                  // MachineDescription::crossControllerFeed
    // Kept as the file has them (no field of their own: set in the file, docs/machines.md).
    QString m_subroutineFolder;
    QString m_subroutineFolderPath;
    machine::LimitPolicy m_limits = machine::LimitPolicy::Clamp;   // "limits" (issue 50)
    machine::ToolLength m_toolLength = machine::ToolLength::Table; // "toolLength" (issue 50)
    bool m_spindleLaser = false; // "spindle": {"laser"} (issue 50), kept as the file has it
    ControllersTable* controllersTable() const { return m_controllers; }
    AxesTable* axesTable() const { return m_axes; }
    QMessageBox* pendingPrompt() const { return m_prompt.data(); }
    // "Re-open machine": shown once the file of the machine the window runs was saved
    // (offerReopen); asks the window to open that machine again from the file.
    QPushButton* reopenButton() const { return m_reopen; }
    // The machine the window runs is the file just saved: note says it still runs on the
    // description it was opened with, and Re-open machine appears.
    void offerReopen(const QString& note);
    // A note in the message line (the outcome of a re-open).
    void showNote(const QString& text, bool isError) { showMessage(text, isError); }

public Q_SLOTS:
    void save();       // to path(), or Save as when there is none
    void saveAs();     // asks for a file (non-modal)
    void chooseFile(); // Open: asks for a file, after the unsaved-changes question

Q_SIGNALS:
    void saved(const QString& path);
    void reopenRequested(const QString& path);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void build();
    QHBoxLayout* buildNameRow();
    QWidget* buildButtons();
    void revalidate();
    bool readMachine(machine::MachineDescription* out, machine::MachineFileError* error) const;
    void mark(const QList<QWidget*>& cells);
    void showMessage(const QString& text, bool isError);
    void setModified(bool modified);
    void saveAsThen(std::function<void()> next);
    // Runs next now, or after the operator chose to save or discard the unsaved changes.
    void afterUnsavedChanges(std::function<void()> next);

    QLineEdit* m_name = nullptr;
    QLineEdit* m_maxRpm = nullptr;
    ControllersTable* m_controllers = nullptr;
    AxesTable* m_axes = nullptr;
    ElidedLabel* m_message = nullptr;
    QPushButton* m_reopen = nullptr;
    QString m_path;
    bool m_modified = false;
    bool m_closing = false; // the operator already answered the unsaved-changes question
    machine::MachineFileError m_error;
    QList<QPointer<QWidget>> m_marked; // rows may be removed meanwhile
    QPointer<QMessageBox> m_prompt;
};

} // namespace stepdeck::ui
