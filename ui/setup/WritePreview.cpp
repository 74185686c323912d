#include "WritePreview.h"
#include "setup/ParameterField.h"
#include "setup/WriteWarnings.h"
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {

QString shown(const ParameterSpec& spec, const QVariant& v)
{
    switch (spec.type) {
    case ParameterType::Boolean:
        return v.toBool() ? WritePreview::tr("on") : WritePreview::tr("off");
    case ParameterType::Choice:
        return ParameterField::translatedChoice(v.toString());
    case ParameterType::Integer:
        break;
    }
    return v.toString();
}

QVariant valueOf(const ParameterSet& set, const QString& name, std::optional<Axis> axis)
{
    const ParameterValue v = set.value(name);
    return axis ? v.perAxis.value(*axis) : v.global;
}

// The old value: the one the device last reported; one written since and not read back
// says so; never a default: what is not known says so.
QString oldText(const ParameterSpec& spec, const WritePreview::OnDevice& onDevice,
                std::optional<Axis> axis)
{
    const QVariant read = valueOf(onDevice.readBack, spec.name, axis);
    if (read.isValid())
        return shown(spec, read);
    const QVariant known = valueOf(onDevice.known, spec.name, axis);
    if (known.isValid())
        return WritePreview::tr("%1 (written, not read back)").arg(shown(spec, known));
    return spec.readable ? WritePreview::tr("unknown (not read)")
                         : WritePreview::tr("unknown (cannot be read back)");
}
} // namespace

QList<WritePreview::Row> WritePreview::rows(const ParameterSchema& schema, const ParameterSet& set,
                                            const QMap<Axis, int>& driveAddresses,
                                            const OnDevice& onDevice, const AxisNames& names)
{
    QMap<QString, QList<Row>> byDrive; // grouped per drive, drives in axis order
    QList<Row> global;
    for (const ParameterSpec& spec : schema.specs()) {
        if (!set.contains(spec.name))
            continue;
        const ParameterValue& v = set.value(spec.name);
        if (!v.isPerAxis()) {
            global << Row{tr("all"), ParameterSchema::displayText(spec.label),
                          oldText(spec, onDevice, std::nullopt), shown(spec, v.global),
                          ParameterSchema::displayUnitColumn(spec)};
            continue;
        }
        for (auto a = v.perAxis.cbegin(); a != v.perAxis.cend(); ++a) {
            const QString drive = driveAddresses.contains(a.key())
                                      ? tr("Drive %1 (%2)")
                                            .arg(driveAddresses.value(a.key()))
                                            .arg(names.name(a.key()))
                                      : names.name(a.key());
            byDrive[QStringLiteral("%1").arg(a.key().index(), 3, 10, QLatin1Char('0')) + drive]
                << Row{drive, ParameterSchema::displayText(spec.label),
                       oldText(spec, onDevice, a.key()), shown(spec, a.value()),
                       ParameterSchema::displayUnitColumn(spec)};
        }
    }
    QList<Row> out = global;
    for (const QList<Row>& drive : std::as_const(byDrive))
        out << drive;
    return out;
}

WritePreview::WritePreview(const ParameterSchema& schema, const ParameterSet& set,
                           const QMap<Axis, int>& driveAddresses, const OnDevice& onDevice,
                           const AxisNames& names, QWidget* parent)
    : QDialog(parent), m_table(new QTableWidget(this))
{
    setObjectName(QStringLiteral("writePreview"));
    setWindowTitle(tr("Write parameters"));
    const QList<Row> list = rows(schema, set, driveAddresses, onDevice, names);
    auto* intro = new QLabel(
        tr("These %n value(s) will be sent, and nothing else:", nullptr, int(list.size())), this);
    intro->setWordWrap(true);
    m_table->setColumnCount(5);
    m_table->setHorizontalHeaderLabels(
        {tr("Drive"), tr("Parameter"), tr("Old"), tr("New"), tr("Unit")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setRowCount(int(list.size()));
    for (int r = 0; r < list.size(); ++r) {
        const Row& row = list.at(r);
        const QStringList cells{row.drive, row.parameter, row.old, row.value, row.unit};
        for (int c = 0; c < cells.size(); ++c)
            m_table->setItem(r, c, new QTableWidgetItem(cells.at(c)));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* layout = new QVBoxLayout(this);
    const QStringList warnings = WriteWarnings::collect(schema, set);
    if (!warnings.isEmpty()) {
        auto* warn = new QLabel(
            tr("Please read before writing:<br>%1").arg(warnings.join(QStringLiteral("<br>"))),
            this);
        warn->setWordWrap(true);
        warn->setStyleSheet(QStringLiteral("QLabel { background:#ffe082; padding:6px; }"));
        layout->addWidget(warn);
    }
    layout->addWidget(intro);
    layout->addWidget(m_table, 1);
    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(tr("Write"), QDialogButtonBox::AcceptRole)
        ->setObjectName(QStringLiteral("writeButton"));
    buttons->addButton(QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(560, 420);
}

int WritePreview::rowCount() const
{
    return m_table->rowCount();
}

} // namespace stepdeck::ui
