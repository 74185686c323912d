#pragma once
#include "model/AxisNames.h"
#include "model/ParameterSchema.h"
#include <QDialog>

class QCheckBox;
class QTableWidget;

namespace stepdeck::ui {

// Shows what a loaded parameter file changes compared with the form, before anything is
// written; "Changes only" (on at first) hides the rows the file leaves as they are. The
// operator chooses: load into the form, load and write, or cancel.
class DiffDialog : public QDialog
{
    Q_OBJECT
public:
    enum Choice { Cancel = 0, LoadIntoForm = 1, LoadAndWrite = 2 };

    struct Row
    {
        QString parameter; // translated label
        QString axis;      // "X" or empty for global
        QString current;
        QString loaded;
        bool differs = false;
    };
    // names: the controller's names of its axes.
    static QList<Row> compare(const ParameterSchema& schema, const ParameterSet& current,
                              const ParameterSet& loaded, const AxisNames& names = {});

    DiffDialog(const QList<Row>& rows, const QString& fileName, QWidget* parent = nullptr);
    int changedCount() const { return m_changed; }
    QTableWidget* table() const { return m_table; }
    QCheckBox* changesOnlyBox() const { return m_changesOnly; }
    int visibleRowCount() const;

private:
    void fillTable(); // the rows, the changed ones highlighted; counts them
    void showRows(bool changesOnly);

    QList<Row> m_rows;
    QTableWidget* m_table;
    QCheckBox* m_changesOnly;
    int m_changed = 0;
};

} // namespace stepdeck::ui
