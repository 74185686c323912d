#include "RecordsPage.h"
#include "RecordDelegate.h"
#include "machine/MachineContext.h"
#include "model/ModelOperations.h"
#include <QComboBox>
#include <QCompleter>
#include <QCoreApplication>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
constexpr int kRecords = 32; // Nanotec section 4: records 1..32 in the EEPROM

QTableWidgetItem* readOnlyCell(const QVariant& value)
{
    auto* item = new QTableWidgetItem;
    item->setData(Qt::DisplayRole, value);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}
} // namespace

RecordsPage::RecordsPage(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_axis(new QComboBox(this)),
      m_record(new QSpinBox(this)), m_table(new QTableWidget(kRecords, 0, this)),
      m_errors(new QTableWidget(0, 4, this)), m_delegate(new RecordDelegate(this)),
      m_state(new QLabel(this)), m_lastError(new QLabel(this))
{
    m_axis->setObjectName(QStringLiteral("recordAxis"));
    m_record->setObjectName(QStringLiteral("recordNumber"));
    m_table->setObjectName(QStringLiteral("recordTable"));
    m_errors->setObjectName(QStringLiteral("errorMemoryTable"));
    m_record->setRange(1, kRecords);

    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Drive:"), this));
    top->addWidget(m_axis);
    top->addWidget(new QLabel(tr("Record:"), this));
    top->addWidget(m_record);
    auto button = [this, top](const QString& text, const QString& tip,
                              void (RecordsPage::*slot)()) {
        auto* b = new QPushButton(text, this);
        b->setToolTip(tip);
        connect(b, &QPushButton::clicked, this, slot);
        top->addWidget(b);
        m_buttons << b;
    };
    button(tr("Read all"), tr("Read records 1..32 from the drive's EEPROM ('Z<n>|', 6.4)"),
           &RecordsPage::readAll);
    button(tr("Write record"),
           tr("Write the selected row into the record, store it and read it back (6.5)"),
           &RecordsPage::writeRecord);
    button(tr("Save to EEPROM"),
           tr("Store the drive's current settings (RAM) as the selected record ('>', 6.5)"),
           &RecordsPage::saveRecord);
    button(tr("Load record"),
           tr("Load the selected record into the drive's current settings ('y', 6.3)"),
           &RecordsPage::loadRecord);
    top->addStretch(1);

    auto* errorBox = new QGroupBox(tr("Error memory"), this);
    auto* ev = new QVBoxLayout(errorBox);
    auto* errorRow = new QHBoxLayout;
    auto* readErrors = new QPushButton(tr("Read error memory"), errorBox);
    connect(readErrors, &QPushButton::clicked, this, &RecordsPage::readErrorMemory);
    m_buttons << readErrors;
    errorRow->addWidget(readErrors);
    errorRow->addWidget(m_lastError, 1);
    ev->addLayout(errorRow);
    ev->addWidget(m_errors);
    m_errors->setHorizontalHeaderLabels({tr("Slot"), tr("Code"), tr("Error"), tr("Meaning")});
    m_errors->verticalHeader()->hide();
    m_errors->horizontalHeader()->setStretchLastSection(true);
    m_errors->setEditTriggers(QAbstractItemView::NoEditTriggers);

    m_table->setItemDelegate(m_delegate);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    QStringList rows;
    for (int n = 1; n <= kRecords; ++n)
        rows << QString::number(n);
    m_table->setVerticalHeaderLabels(rows);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) {
        if (row >= 0)
            m_record->setValue(row + 1);
    });
    connect(m_record, &QSpinBox::valueChanged, this, [this](int n) {
        if (m_table->currentRow() != n - 1)
            m_table->setCurrentCell(n - 1, qMax(0, m_table->currentColumn()));
    });

    auto* v = new QVBoxLayout(this);
    v->addLayout(top);
    v->addWidget(m_table, 3);
    v->addWidget(m_state);
    v->addWidget(errorBox, 2);

    ControllerSession* session = m_context->session();
    connect(session, &ControllerSession::requestFinished, this, &RecordsPage::onResult);
    connect(session, &ControllerSession::linkStateChanged, this, &RecordsPage::updateEnabled);
    connect(m_context, &MachineContext::modelChanged, this, &RecordsPage::rebuild);
    rebuild();
}

RecordsPage::~RecordsPage()
{
    // The drive field's "left without picking" must not run while QWidget deletes the combo
    // (a focused, edited field loses its focus then).
    if (m_axis->lineEdit())
        m_axis->lineEdit()->disconnect(this);
}

QString RecordsPage::stateText() const
{
    return m_state->text();
}

void RecordsPage::rebuild()
{
    const QString current = m_axis->currentData().toString();
    m_axis->clear();
    const QList<Axis> axes = m_context->axes();
    for (Axis a : axes)
        m_axis->addItem(tr("Axis %1").arg(m_context->controllerAxisName(a)), axisName(a));
    makeFindable(axes.size() > kPlainListAxes);
    const int keep = m_axis->findData(current);
    if (keep >= 0)
        m_axis->setCurrentIndex(keep);
    updateEnabled();
}

void RecordsPage::makeFindable(bool findable)
{
    // A bus of many drives (issue 32, step 5): the drive is found by typing part of its name;
    // the list offers every drive whose name contains it. Typing never picks a drive by
    // itself: the text goes back to the chosen drive's when the field is left, so what shows
    // is the drive the records are read from.
    if (findable == m_axis->isEditable())
        return;
    m_axis->setEditable(findable);
    if (!findable)
        return;
    m_axis->setInsertPolicy(QComboBox::NoInsert);
    m_axis->lineEdit()->setPlaceholderText(tr("Type part of a drive's name"));
    QCompleter* completer = m_axis->completer();
    completer->setFilterMode(Qt::MatchContains);
    completer->setCaseSensitivity(Qt::CaseInsensitive);
    completer->setCompletionMode(QCompleter::PopupCompletion);
    connect(m_axis->lineEdit(), &QLineEdit::editingFinished, this, [this] {
        if (!m_axis->lineEdit()->hasFocus()) // left, not Enter (which picks a matching drive)
            m_axis->setEditText(m_axis->itemText(m_axis->currentIndex()));
    });
}

QVariantMap RecordsPage::target() const
{
    return {{operation::arg::kAxis, m_axis->currentData().toString()},
            {operation::arg::kRecord, m_record->value()}};
}

void RecordsPage::start(Pending what, const QString& operation, const QVariantMap& args,
                        const QString& message)
{
    if (m_pending || !m_context->isConnected())
        return;
    m_what = what;
    m_state->setText(message);
    m_pending = m_context->session()->modelOperation(operation, args);
    updateEnabled();
}

void RecordsPage::readAll()
{
    start(Pending::ReadAll, operation::kReadAllRecords,
          {{operation::arg::kAxis, m_axis->currentData().toString()}},
          tr("Reading records 1..%1 of axis %2\u2026")
              .arg(kRecords)
              .arg(m_context->controllerAxisName(
                  axisFromName(m_axis->currentData().toString()).value_or(Axis::X))));
}

void RecordsPage::writeRecord()
{
    const int row = m_record->value() - 1;
    QVariantMap values;
    for (int c = 0; c < m_columns.size(); ++c) {
        if (const QTableWidgetItem* item = m_table->item(row, c))
            values.insert(m_columns.at(c), item->data(Qt::EditRole));
    }
    if (values.isEmpty()) {
        m_state->setText(
            tr("Read the records first: there is nothing to write for record %1.").arg(row + 1));
        return;
    }
    QVariantMap args = target();
    args.insert(operation::arg::kValues, values);
    start(Pending::Write, operation::kWriteRecord, args,
          tr("Writing record %1\u2026").arg(row + 1));
}

void RecordsPage::saveRecord()
{
    start(Pending::Save, operation::kSaveRecord, target(),
          tr("Saving the current settings as record %1\u2026").arg(m_record->value()));
}

void RecordsPage::loadRecord()
{
    start(Pending::Load, operation::kLoadRecord, target(),
          tr("Loading record %1\u2026").arg(m_record->value()));
}

void RecordsPage::readErrorMemory()
{
    start(Pending::Errors, operation::kReadErrorMemory,
          {{operation::arg::kAxis, m_axis->currentData().toString()}},
          tr("Reading the error memory\u2026"));
}

void RecordsPage::onResult(const CommandResult& result)
{
    if (!m_pending || result.id != m_pending)
        return;
    const Pending what = m_what;
    m_pending = 0;
    m_what = Pending::None;
    updateEnabled();
    if (!result.ok()) {
        m_state->setText(tr("Failed: %1").arg(result.message));
        return;
    }
    const QVariantMap one = result.value.toMap();
    switch (what) {
    case Pending::ReadAll:
        onRecords(result.value.toList());
        m_state->setText(tr("%n record(s) read.", nullptr, m_table->rowCount()));
        break;
    case Pending::Write:
        setRow(one.value(QStringLiteral("record")).toInt() - 1,
               one.value(QStringLiteral("values")).toMap());
        m_state->setText(tr("Record %1 written, saved and verified.")
                             .arg(one.value(QStringLiteral("record")).toInt()));
        break;
    case Pending::Save:
    case Pending::Load:
        setRow(one.value(QStringLiteral("record")).toInt() - 1,
               one.value(QStringLiteral("values")).toMap());
        m_state->setText(what == Pending::Save
                             ? tr("Current settings saved as record %1.")
                                   .arg(one.value(QStringLiteral("record")).toInt())
                             : tr("Record %1 loaded into the drive's current settings.")
                                   .arg(one.value(QStringLiteral("record")).toInt()));
        break;
    case Pending::Errors:
        onErrors(one);
        m_state->clear();
        break;
    case Pending::None:
        break;
    }
}

QString RecordsPage::columnTitle(const QString& name) const
{
    const ParameterSchema schema = m_context->schema();
    const ParameterSpec* spec = schema.find(name);
    if (!spec)
        return name;
    QString title = ParameterSchema::displayText(spec->label);
    if (!spec->unit.isEmpty())
        title += QStringLiteral(" [%1]").arg(spec->unit);
    return title;
}

void RecordsPage::onRecords(const QVariantList& records)
{
    QStringList columns;
    for (const QVariant& r : records) {
        const QVariantMap values = r.toMap().value(QStringLiteral("values")).toMap();
        for (auto it = values.cbegin(); it != values.cend(); ++it)
            if (!columns.contains(it.key()))
                columns << it.key();
    }
    // Keep the schema's order (the manual's), not the alphabetical one of the maps.
    QStringList ordered;
    const ParameterSchema schema = m_context->schema();
    for (const ParameterSpec& spec : schema.specs())
        if (columns.contains(spec.name))
            ordered << spec.name;
    for (const QString& c : std::as_const(columns))
        if (!ordered.contains(c))
            ordered << c;
    m_columns = ordered;
    QList<ParameterSpec> specs;
    for (const QString& c : std::as_const(m_columns)) {
        const ParameterSpec* spec = schema.find(c);
        specs << (spec ? *spec : ParameterSpec{});
    }
    m_delegate->setColumns(specs);
    m_table->clearContents();
    m_table->setColumnCount(int(m_columns.size()));
    QStringList titles;
    for (const QString& c : std::as_const(m_columns))
        titles << columnTitle(c);
    m_table->setHorizontalHeaderLabels(titles);
    for (const QVariant& r : records) {
        const QVariantMap rec = r.toMap();
        setRow(rec.value(QStringLiteral("record")).toInt() - 1,
               rec.value(QStringLiteral("values")).toMap());
    }
    m_table->resizeColumnsToContents();
}

void RecordsPage::setRow(int row, const QVariantMap& values)
{
    if (row < 0 || row >= m_table->rowCount())
        return;
    for (int c = 0; c < m_columns.size(); ++c) {
        if (!values.contains(m_columns.at(c)))
            continue;
        auto* item = new QTableWidgetItem;
        // The value keeps its type, so the editor is a spin box for numbers.
        item->setData(Qt::EditRole, values.value(m_columns.at(c)));
        m_table->setItem(row, c, item);
    }
}

void RecordsPage::onErrors(const QVariantMap& memory)
{
    const QVariantList entries = memory.value(QStringLiteral("entries")).toList();
    m_errors->setRowCount(int(entries.size()));
    for (int r = 0; r < entries.size(); ++r) {
        const QVariantMap e = entries.at(r).toMap();
        m_errors->setItem(r, 0, readOnlyCell(e.value(QStringLiteral("slot"))));
        m_errors->setItem(r, 1, readOnlyCell(e.value(QStringLiteral("code"))));
        m_errors->setItem(r, 2, readOnlyCell(e.value(QStringLiteral("name"))));
        m_errors->setItem(r, 3, readOnlyCell(e.value(QStringLiteral("description"))));
    }
    m_errors->resizeColumnsToContents();
    m_lastError->setText(
        tr("Last entry: slot %1").arg(memory.value(QStringLiteral("last")).toInt()));
}

void RecordsPage::updateEnabled()
{
    const bool ready = m_context->isConnected() && !m_pending && m_axis->count() > 0;
    for (QPushButton* b : std::as_const(m_buttons))
        b->setEnabled(ready);
}

} // namespace stepdeck::ui
