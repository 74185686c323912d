#pragma once
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include <QWidget>
#include <optional>

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace stepdeck::ui {

class DiffDialog;
class MachineContext;
class ParameterField;

// Setup pages for technicians, generated from the model's ParameterSchema: one group box per
// schema group, one column per axis, range-checked editors, changed fields highlighted;
// Read (where the protocol can), Write, Write & verify, and Save/Load in the CLI's JSON format
// with a diff before a loaded file is written. Invalid values are never written.
class SetupPage : public QWidget
{
    Q_OBJECT
public:
    explicit SetupPage(MachineContext* context, QWidget* parent = nullptr);

    ParameterField* field(const QString& name, std::optional<Axis> axis = std::nullopt) const;
    QPushButton* writeButton() const { return m_write; }
    QPushButton* writeVerifyButton() const { return m_writeVerify; }
    QPushButton* readButton() const { return m_read; }
    QString messageText() const;

    // Every field's value; false and the reasons when a field is invalid.
    bool formValues(ParameterSet* set, QStringList* errors) const;
    QStringList fieldErrors() const;
    // Fields that differ from the device (or whose device value is unknown), whole parameters.
    ParameterSet changedValues() const;
    void applyToForm(const ParameterSet& set);

    bool saveToFile(const QString& path, QString* error) const;
    bool readFile(const QString& path, ParameterSet* set, QString* error) const;

public Q_SLOTS:
    // false: nothing sent (invalid values or nothing changed). confirmWarnings: ask before
    // writing parameters whose schema entry carries a warning (true then means "sent or
    // waiting for the answer").
    bool write(bool verify = false, bool confirmWarnings = false);
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
    QWidget* buildGroup(const QString& group);
    void refreshButtons();
    void onResult(const CommandResult& result);
    void setMessage(const QString& text, bool error);
    void setBaselines(const ParameterSet& set);
    void send(const ParameterSet& set, bool verify);

    MachineContext* m_context;
    ParameterSchema m_schema;
    QVBoxLayout* m_groups;
    QWidget* m_content = nullptr;
    QList<ParameterField*> m_fields;
    QPushButton* m_read;
    QPushButton* m_write;
    QPushButton* m_writeVerify;
    QLabel* m_info;
    QLabel* m_message;
    bool m_anyReadable = false;
    RequestId m_pendingWrite = 0;
    RequestId m_pendingRead = 0;
    ParameterSet m_pendingSet;
};

} // namespace stepdeck::ui
