#pragma once
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include <QPointer>
#include <QWidget>
#include <optional>

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace stepdeck::ui {

class DiffDialog;
class MachineContext;
class ParameterField;
class SetupDriveChooser;
class SetupMessageLine;
class WritePreview;

// Setup pages for technicians, generated from the model's ParameterSchema: one group box per
// schema group, one column per axis (a bus of more drives: the drives SetupDriveChooser
// shows; Write, Write all and Save take those and the global values), range-checked editors,
// changed fields highlighted; Read and Write & verify (only where the protocol can read back),
// Write, Write all, and Save/Load in the CLI's JSON format with a diff before a loaded file is
// written. Invalid values are never written. What counts as already on the device is
// MachineContext::knownParameters() (forgotten on every reconnect, reset and power cycle);
// what Write sends is a WritePlan. A multi-drive model previews exactly what goes to which
// drive, old -> new, before anything is sent (WritePreview).
class SetupPage : public QWidget
{
    Q_OBJECT
public:
    explicit SetupPage(MachineContext* context, QWidget* parent = nullptr);

    // nullptr also for an axis whose column is not shown (a bus of many drives).
    ParameterField* field(const QString& name, std::optional<Axis> axis = std::nullopt) const;
    SetupDriveChooser* driveChooser() const { return m_driveChooser; }
    QPushButton* writeButton() const { return m_write; }
    QPushButton* writeVerifyButton() const { return m_writeVerify; }
    QPushButton* readButton() const { return m_read; }
    QPushButton* writeAllButton() const { return m_writeAll; }
    WritePreview* openPreview() const; // the last preview, while open
    QString messageText() const;
    // A read of the parameters is on its way (Read, or the read-back after connecting).
    bool isReading() const { return m_pendingRead != 0; }

    // Every field's value; false and the reasons when a field is invalid.
    bool formValues(ParameterSet* set, QStringList* errors) const;
    QStringList fieldErrors() const;
    // What Write would send now (WritePlan, scope Changed).
    ParameterSet changedValues() const;
    // Values the technician chose (a file, the defaults): explicit, shown as changed.
    void applyToForm(const ParameterSet& set);

    bool saveToFile(const QString& path, QString* error) const;
    bool readFile(const QString& path, ParameterSet* set, QString* error) const;

public Q_SLOTS:
    // false: nothing sent (invalid values or nothing to write; the message says why).
    // confirm: show the preview (multi-drive) or the schema's warnings first, when there are
    // any (true then means "sent or waiting for the answer").
    bool write(bool verify = false, bool confirm = false);
    bool writeAll(bool verify = false, bool confirm = false);
    void read();
    void resetToDefaults();
    void saveAs();
    void load();
    // Shows what the file changes (non-modal); the technician loads, loads and writes, or
    // cancels. nullptr when the file cannot be read (the message says why).
    DiffDialog* loadFile(const QString& path);

Q_SIGNALS:
    void message(const QString& text);

private:
    void rebuild();
    void buildForm();  // the groups for the drives shown
    void showDrives(); // the chooser picked other drives: their columns, unless edits pending
    QWidget* buildGroup(const QString& group);
    void refreshButtons();
    void onResult(const CommandResult& result);
    void setMessage(const QString& text, bool error, const QStringList& details = {});
    static QString invalidText(const QStringList& errors);
    // Baselines from what the context knows on the device; fields without the technician's
    // choice show those values (also ones written elsewhere: the machine file's setup).
    void applyKnown();
    void markReadableUnknown();           // readable values not read (yet): unknown, not defaults
    void showWhetherAnythingIsSettable(); // no writable parameter: no form buttons, a reason
    bool hasSettableParameters();         // false: says why
    static QString noParametersText();
    void showRead(const ParameterSet& set);
    bool writePlanned(int scope, bool verify, bool confirm);
    bool writeSet(const ParameterSet& set, bool verify, bool confirm);
    void send(const ParameterSet& set, bool verify);

    MachineContext* m_context;
    ParameterSchema m_schema;
    QVBoxLayout* m_groups;
    QWidget* m_content = nullptr;
    QList<ParameterField*> m_fields;
    QPushButton* m_read;
    QPushButton* m_write;
    QPushButton* m_writeVerify;
    QPushButton* m_writeAll;
    QList<QPushButton*> m_formButtons; // Defaults, Save to file, Load from file
    QPointer<WritePreview> m_preview;
    QLabel* m_info;
    SetupMessageLine* m_message;
    SetupDriveChooser* m_driveChooser;
    bool m_anyReadable = false;
    RequestId m_pendingWrite = 0;
    RequestId m_pendingRead = 0;
    ParameterSet m_pendingSet;
    bool m_pendingVerify = false;
};

} // namespace stepdeck::ui
