#include "EditorTable.h"
#include "model/NumberParsing.h"
#include <QApplication>
#include <QComboBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QScrollBar>

namespace stepdeck::ui {

EditorTable::EditorTable(const QStringList& keys, const QStringList& headers, int visibleRows,
                         QWidget* parent)
    : QTableWidget(0, int(keys.size()), parent), m_keys(keys), m_visibleRows(visibleRows)
{
    setHorizontalHeaderLabels(headers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers); // the cell widgets edit
    verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    verticalHeader()->setDefaultSectionSize(QLineEdit().sizeHint().height() + 4);
    horizontalHeader()->setStretchLastSection(true);
    horizontalHeader()->setHighlightSections(false);
    for (int c = 0; c < columnCount(); ++c) // the header's text decides the narrowest width
        setColumnWidth(c,
                       horizontalHeader()->fontMetrics().horizontalAdvance(headers.value(c)) + 24);
}

QList<QWidget*> EditorTable::cells(int row, const QString& key) const
{
    const int column = columnOf(key);
    if (row < 0 || row >= rowCount() || column < 0)
        return {};
    QWidget* w = cellWidget(row, column);
    return w ? QList<QWidget*>{w} : QList<QWidget*>{};
}

QWidget* EditorTable::cell(int row, const QString& key) const
{
    const QList<QWidget*> found = cells(row, key);
    return found.isEmpty() ? nullptr : found.first();
}

int EditorTable::currentEditRow() const
{
    const QWidget* focus = QApplication::focusWidget();
    for (int r = 0; focus && r < rowCount(); ++r) {
        for (int c = 0; c < columnCount(); ++c) {
            const QWidget* w = cellWidget(r, c);
            if (w && (w == focus || w->isAncestorOf(focus)))
                return r;
        }
    }
    return currentRow();
}

QSize EditorTable::sizeHint() const
{
    // Every column and m_visibleRows rows, no scroll bar: the editor fits 1366x768 with this.
    const int frame = 2 * frameWidth();
    const int width = verticalHeader()->sizeHint().width() + horizontalHeader()->length() + frame;
    const int height = horizontalHeader()->sizeHint().height() +
                       m_visibleRows * verticalHeader()->defaultSectionSize() + frame;
    return {width, height};
}

QSize EditorTable::minimumSizeHint() const
{
    return {sizeHint().width(), sizeHint().height()};
}

QLineEdit* EditorTable::addLineCell(int row, const QString& key, const QString& text, int width)
{
    auto* edit = new QLineEdit(text);
    edit->setFrame(false);
    connect(edit, &QLineEdit::textEdited, this, &EditorTable::edited);
    setCellWidget(row, columnOf(key), edit);
    fitColumn(key, width);
    return edit;
}

QComboBox* EditorTable::addComboCell(int row, const QString& key, int width)
{
    auto* combo = new QComboBox;
    combo->setFrame(false);
    setCellWidget(row, columnOf(key), combo);
    fitColumn(key, width);
    return combo;
}

void EditorTable::fitColumn(const QString& key, int width)
{
    const int column = columnOf(key);
    if (columnWidth(column) < width)
        setColumnWidth(column, width);
    updateGeometry();
}

void EditorTable::removeRowAndNotify(int row)
{
    if (row < 0 || row >= rowCount())
        return;
    removeRow(row);
    Q_EMIT edited();
}

int EditorTable::rowOf(const QWidget* cellWidget, const QString& key) const
{
    for (int r = 0; r < rowCount(); ++r) {
        if (cell(r, key) == cellWidget)
            return r;
    }
    return -1;
}

bool readDecimal(const QLineEdit* edit, const QString& path, bool optional,
                 std::optional<double>* value, machine::MachineFileError* error)
{
    const QString text = edit->text().trimmed();
    *value = std::nullopt;
    if (text.isEmpty() && optional)
        return true;
    double number = 0;
    if (numbers::parseReal(text, &number) != NumberError::None)
        return machine::MachineFileError::report(
            error, path,
            QCoreApplication::translate("stepdeck::ui::EditorTable",
                                        "must be a decimal number like 88.8889 (is \"%1\")")
                .arg(text));
    *value = number;
    return true;
}

} // namespace stepdeck::ui
