#include "DiffDialog.h"
#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
QString displayValue(const ParameterSpec& spec, const QVariant& v)
{
    if (!v.isValid())
        return QCoreApplication::translate("stepdeck::ui::DiffDialog", "(not set)");
    if (spec.type == ParameterType::Boolean)
        return v.toBool() ? QCoreApplication::translate("stepdeck::ui::DiffDialog", "on")
                          : QCoreApplication::translate("stepdeck::ui::DiffDialog", "off");
    if (spec.type == ParameterType::Choice)
        return ParameterSchema::displayText(v.toString());
    return v.toString();
}
} // namespace

QList<DiffDialog::Row> DiffDialog::compare(const ParameterSchema& schema,
                                           const ParameterSet& current, const ParameterSet& loaded,
                                           const AxisNames& names)
{
    QList<Row> rows;
    for (const ParameterSpec& spec : schema.specs()) {
        if (!loaded.contains(spec.name))
            continue;
        const QString label = ParameterSchema::displayText(spec.label);
        const ParameterValue now = current.value(spec.name);
        const ParameterValue then = loaded.value(spec.name);
        if (spec.perAxis) {
            for (auto it = then.perAxis.cbegin(); it != then.perAxis.cend(); ++it) {
                const QVariant before = now.perAxis.value(it.key());
                rows << Row{label, names.name(it.key()), displayValue(spec, before),
                            displayValue(spec, it.value()),
                            schema.normalise(spec, before) != schema.normalise(spec, it.value())};
            }
        } else {
            rows << Row{label, QString(), displayValue(spec, now.global),
                        displayValue(spec, then.global),
                        schema.normalise(spec, now.global) != schema.normalise(spec, then.global)};
        }
    }
    return rows;
}

DiffDialog::DiffDialog(const QList<Row>& rows, const QString& fileName, QWidget* parent)
    : QDialog(parent), m_rows(rows), m_table(new QTableWidget(int(rows.size()), 4, this)),
      m_changesOnly(new QCheckBox(tr("Changes only"), this))
{
    setWindowTitle(tr("Load parameters"));
    QTableWidget* table = m_table;
    table->setHorizontalHeaderLabels({tr("Parameter"), tr("Axis"), tr("Form"), tr("File")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    fillTable();
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table->resizeColumnsToContents();
    // On at first: a technician loading a file asks "what does it change?", and a full
    // parameter file (every parameter, every axis or drive) buries the few rows that differ
    // among dozens that do not. Off shows the whole file, the changes highlighted.
    m_changesOnly->setObjectName(QStringLiteral("diffChangesOnly"));
    m_changesOnly->setToolTip(tr("Hide the values the file leaves as they are"));
    m_changesOnly->setChecked(true);
    connect(m_changesOnly, &QCheckBox::toggled, this, &DiffDialog::showRows);
    showRows(true);

    auto* summary = new QLabel(
        m_changed == 0
            ? tr("%1 holds the same values as the form.").arg(fileName)
            : tr("%1 changes %n value(s) (highlighted).", nullptr, m_changed).arg(fileName),
        this);
    summary->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(this);
    QPushButton* load = buttons->addButton(tr("Load into form"), QDialogButtonBox::AcceptRole);
    QPushButton* write = buttons->addButton(tr("Load and write"), QDialogButtonBox::ApplyRole);
    buttons->addButton(QDialogButtonBox::Cancel);
    connect(load, &QPushButton::clicked, this, [this] { done(LoadIntoForm); });
    connect(write, &QPushButton::clicked, this, [this] { done(LoadAndWrite); });
    connect(buttons, &QDialogButtonBox::rejected, this, [this] { done(Cancel); });

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary);
    layout->addWidget(m_changesOnly);
    layout->addWidget(table);
    layout->addWidget(buttons);
    resize(620, 420);
}

void DiffDialog::fillTable()
{
    for (int r = 0; r < m_rows.size(); ++r) {
        const Row& row = m_rows.at(r);
        const QStringList cells{row.parameter, row.axis, row.current, row.loaded};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells.at(c));
            if (row.differs) {
                item->setBackground(QColor(0xff, 0xf5, 0x9d));
                QFont f = item->font();
                f.setBold(c == 3);
                item->setFont(f);
            }
            m_table->setItem(r, c, item);
        }
        m_changed += row.differs ? 1 : 0;
    }
}

void DiffDialog::showRows(bool changesOnly)
{
    for (int r = 0; r < m_rows.size(); ++r)
        m_table->setRowHidden(r, changesOnly && !m_rows.at(r).differs);
}

int DiffDialog::visibleRowCount() const
{
    int n = 0;
    for (int r = 0; r < m_table->rowCount(); ++r)
        n += m_table->isRowHidden(r) ? 0 : 1;
    return n;
}

} // namespace stepdeck::ui
