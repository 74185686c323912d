#pragma once
#include "machine/MachineFile.h"
#include <QTableWidget>

class QComboBox;
class QLineEdit;

namespace stepdeck::ui {

// The common part of the machine editor's two tables: one row per entry, one editing widget
// per cell (so every edit is seen as typed), columns named by the file's keys so that a
// validator error like "axes[3].stepsPerUnit" finds its cell, and a size that shows every
// column and a given number of rows without scrolling.
class EditorTable : public QTableWidget
{
    Q_OBJECT
public:
    // keys: the file key of each column, in order ("stepsPerUnit"); headers: their titles.
    EditorTable(const QStringList& keys, const QStringList& headers, int visibleRows,
                QWidget* parent = nullptr);

    // The widgets of row's field `key` (a file key such as "stepsPerUnit" or
    // "reference.direction"); several for a field spread over columns ("softLimits").
    virtual QList<QWidget*> cells(int row, const QString& key) const;
    QWidget* cell(int row, const QString& key) const;
    int columnOf(const QString& key) const { return m_keys.indexOf(key); }
    // The row the focus or selection is in (-1: none).
    int currentEditRow() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    void edited();

protected:
    QLineEdit* addLineCell(int row, const QString& key, const QString& text, int width);
    QComboBox* addComboCell(int row, const QString& key, int width);
    // Widens the column of key to fit its widest cell widget (set when a row is built).
    void fitColumn(const QString& key, int width);
    void removeRowAndNotify(int row);
    // The row whose cell of key is cellWidget (-1: none); rows move when others are removed.
    int rowOf(const QWidget* cellWidget, const QString& key) const;

private:
    QStringList m_keys;
    int m_visibleRows;
};

// A text cell that must hold a decimal: false with *error ("<path>: must be a decimal ...")
// when it does not. Empty text is *value = nullopt when optional, else an error.
bool readDecimal(const QLineEdit* edit, const QString& path, bool optional,
                 std::optional<double>* value, machine::MachineFileError* error);

} // namespace stepdeck::ui
