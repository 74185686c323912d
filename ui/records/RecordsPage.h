#pragma once
#include "model/CommandResult.h"
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepdeck::ui {

class MachineContext;
class RecordDelegate;

// The technician's page for a drive's stored records (Nanotec section 4, 6.3-6.5) and its
// error memory (5.15), all through the model's operations (operation::kReadAllRecords,
// kWriteRecord, kSaveRecord, kLoadRecord, kReadErrorMemory); shown for models with
// Capabilities::records. Values are the schema's (names, units, choices), never bytes.
class RecordsPage : public QWidget
{
    Q_OBJECT
public:
    explicit RecordsPage(MachineContext* context, QWidget* parent = nullptr);
    ~RecordsPage() override;

    QComboBox* axisCombo() const { return m_axis; }
    QSpinBox* recordSpin() const { return m_record; }
    QTableWidget* recordTable() const { return m_table; }
    QTableWidget* errorTable() const { return m_errors; }
    QString stateText() const;
    // The parameter names of the record table's columns.
    QStringList columns() const { return m_columns; }
    bool busy() const { return m_pending != 0; }

public Q_SLOTS:
    void readAll();
    void writeRecord(); // the selected record's row: write, save and verify
    void saveRecord();  // RAM -> EEPROM record n ('>')
    void loadRecord();  // EEPROM record n -> RAM ('y')
    void readErrorMemory();

private:
    enum class Pending { None, ReadAll, Write, Save, Load, Errors };
    QVariantMap target() const;
    // More drives than this: the drive combo filters by typed name (issue 32, step 5).
    static constexpr int kPlainListAxes = 4;
    void makeFindable(bool findable);
    void start(Pending what, const QString& operation, const QVariantMap& args,
               const QString& message);
    void onResult(const CommandResult& result);
    void onRecords(const QVariantList& records);
    void setRow(int row, const QVariantMap& values);
    void onErrors(const QVariantMap& memory);
    QString columnTitle(const QString& name) const;
    void rebuild();
    void updateEnabled();

    MachineContext* m_context;
    QComboBox* m_axis;
    QSpinBox* m_record;
    QTableWidget* m_table;
    QTableWidget* m_errors;
    RecordDelegate* m_delegate;
    QLabel* m_state;
    QLabel* m_lastError;
    QList<QPushButton*> m_buttons;
    QStringList m_columns;
    RequestId m_pending = 0;
    Pending m_what = Pending::None;
};

} // namespace stepdeck::ui
