#pragma once
#include "model/ParameterSchema.h"
#include <QDialog>

class QTableWidget;

namespace stepdeck::ui {

// Shows what a loaded parameter file changes compared with the form, before anything is
// written. The operator chooses: load into the form, load and write, or cancel.
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
    static QList<Row> compare(const ParameterSchema& schema, const ParameterSet& current,
                              const ParameterSet& loaded);

    DiffDialog(const QList<Row>& rows, const QString& fileName, QWidget* parent = nullptr);
    int changedCount() const { return m_changed; }

private:
    int m_changed = 0;
};

} // namespace stepdeck::ui
