#include "ControllersTable.h"
#include "machine/MachineContext.h"
#include "model/NumberParsing.h"
#include "protocols/Registry.h"
#include <QComboBox>
#include <QLineEdit>
#include <QRegularExpression>

namespace stepdeck::ui {

using machine::MachineController;
using machine::MachineFileError;

namespace {
const char* const kLastId = "stepdeckLastId";

QStringList controllerKeys()
{
    return {"id", "model", "port", "axes", "resetLine", "setup"};
}
} // namespace

QString busAddressText(const QMap<Axis, int>& addresses, const AxisNames& names)
{
    QStringList pairs;
    for (const NamedAddress& e : namedAddresses(addresses, names))
        pairs << QStringLiteral("%1=%2").arg(e.name).arg(e.address);
    return pairs.join(QLatin1Char(' '));
}

bool parseBusAddresses(const QString& text, QMap<Axis, int>* addresses, AxisNames* names,
                       QString* error)
{
    addresses->clear();
    *names = AxisNames();
    static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
    const QStringList pairs = text.split(separators, Qt::SkipEmptyParts);
    if (pairs.isEmpty())
        return true; // the model's default addresses
    QList<NamedAddress> list;
    QString why;
    if (!parseNamedAddresses(pairs.join(QLatin1Char(',')), &list, &why) ||
        !assignBusAxes(list, addresses, names, &why)) {
        addresses->clear();
        *names = AxisNames();
        if (error)
            *error = why;
        return false;
    }
    return true;
}

ControllersTable::ControllersTable(QWidget* parent)
    : EditorTable(controllerKeys(),
                  {tr("Id"), tr("Model"), tr("Port"), tr("Bus addresses"), tr("Reset line"),
                   tr("Setup file")},
                  3, parent)
{
    setObjectName(QStringLiteral("controllersTable"));
}

void ControllersTable::setControllers(const QList<MachineController>& controllers)
{
    setRowCount(0);
    for (const MachineController& c : controllers)
        addRow(c);
    Q_EMIT idsChanged();
}

void ControllersTable::addRow(const MachineController& c)
{
    const int row = rowCount();
    insertRow(row);
    QLineEdit* id = addLineCell(row, "id", c.id, 110);
    id->setProperty(kLastId, c.id);
    connect(id, &QLineEdit::textEdited, this, [this, id](const QString& text) {
        const QString from = id->property(kLastId).toString();
        id->setProperty(kLastId, text);
        Q_EMIT idRenamed(from, text);
        Q_EMIT idsChanged();
        Q_EMIT edited(); // again: the axes follow the new id only now
    });
    QComboBox* model = addComboCell(row, "model", 250);
    for (const ModelInfo& m : models()) {
        model->addItem(modelDisplayName(m), m.id);
        model->setItemData(model->count() - 1, modelDisplayName(m), Qt::ToolTipRole);
    }
    model->setCurrentIndex(model->findData(c.modelId));
    addLineCell(row, "port", c.port, 170)->setPlaceholderText(tr("/dev/ttyUSB0, tcp://…, sim"));
    QLineEdit* bus = addLineCell(row, "axes", busAddressText(c.busAddresses, c.axisNames), 120);
    bus->setPlaceholderText(tr("default"));
    bus->setToolTip(tr("Controller axis = bus address, e.g. X=1 Y=2 or feeder=5 gate=6 (names: a "
                       "letter, then letters, digits or _; empty: X=1, Y=2, Z=3)"));
    QComboBox* reset = addComboCell(row, "resetLine", 90);
    reset->addItem(tr("none"), QString());
    reset->addItem(QStringLiteral("RTS"), resetLineName(LineSettings::ResetLine::Rts));
    reset->addItem(QStringLiteral("DTR"), resetLineName(LineSettings::ResetLine::Dtr));
    reset->setCurrentIndex(c.resetLine ? reset->findData(resetLineName(*c.resetLine)) : 0);
    QLineEdit* setup = addLineCell(row, "setup", c.setupFile, 150);
    setup->setPlaceholderText(tr("none"));
    setup->setToolTip(tr("A parameter file (as Export writes it), relative to the machine file's "
                         "folder: written to the controller on every connect"));
    applyModel(row);
    connect(model, &QComboBox::currentIndexChanged, this, [this, model] {
        applyModel(rowOf(model, "model"));
        Q_EMIT edited();
    });
    connect(reset, &QComboBox::currentIndexChanged, this, &EditorTable::edited);
}

void ControllersTable::applyModel(int row)
{
    const auto* model = qobject_cast<QComboBox*>(cell(row, "model"));
    const ModelInfo* info = model ? findModel(model->currentData().toString()) : nullptr;
    auto* bus = qobject_cast<QLineEdit*>(cell(row, "axes"));
    auto* reset = qobject_cast<QComboBox*>(cell(row, "resetLine"));
    const bool multiDrive = info && info->capabilities.multiDrive;
    const bool resetLine = info && info->capabilities.resetLine;
    if (!multiDrive)
        bus->clear();
    if (!resetLine)
        reset->setCurrentIndex(0);
    bus->setEnabled(multiDrive);
    reset->setEnabled(resetLine);
}

bool ControllersTable::read(QList<MachineController>* out, MachineFileError* error) const
{
    out->clear();
    for (int r = 0; r < rowCount(); ++r) {
        const QString path = QStringLiteral("controllers[%1].").arg(r);
        MachineController c;
        c.id = qobject_cast<QLineEdit*>(cell(r, "id"))->text().trimmed();
        c.modelId = qobject_cast<QComboBox*>(cell(r, "model"))->currentData().toString();
        c.port = qobject_cast<QLineEdit*>(cell(r, "port"))->text().trimmed();
        const QString bus = qobject_cast<QLineEdit*>(cell(r, "axes"))->text();
        QString why;
        if (!parseBusAddresses(bus, &c.busAddresses, &c.axisNames, &why))
            return MachineFileError::report(
                error, path + QStringLiteral("axes"),
                tr("write controller axis = bus address, like X=1 Y=2 or feeder=5 (is \"%1\": %2)")
                    .arg(bus, why));
        const QString reset =
            qobject_cast<QComboBox*>(cell(r, "resetLine"))->currentData().toString();
        c.resetLine = resetLineFromName(reset);
        c.setupFile = qobject_cast<QLineEdit*>(cell(r, "setup"))->text().trimmed();
        *out << c;
    }
    return true;
}

QStringList ControllersTable::ids() const
{
    QStringList list;
    for (int r = 0; r < rowCount(); ++r)
        list << qobject_cast<QLineEdit*>(cell(r, "id"))->text().trimmed();
    return list;
}

QMap<QString, ControllerAxes> ControllersTable::controllerAxes() const
{
    QMap<QString, ControllerAxes> axes;
    for (int r = 0; r < rowCount(); ++r) {
        const QString id = qobject_cast<QLineEdit*>(cell(r, "id"))->text().trimmed();
        const ModelInfo* model =
            findModel(qobject_cast<QComboBox*>(cell(r, "model"))->currentData().toString());
        QMap<Axis, int> addresses;
        AxisNames names;
        if (parseBusAddresses(qobject_cast<QLineEdit*>(cell(r, "axes"))->text(), &addresses,
                              &names) &&
            !addresses.isEmpty())
            axes.insert(id, ControllerAxes{addresses.keys(), names});
        else if (model)
            axes.insert(id, ControllerAxes{model->capabilities.axes, {}});
    }
    return axes;
}

void ControllersTable::addController()
{
    MachineController c;
    const QStringList used = ids();
    for (int n = used.size() + 1; c.id.isEmpty() || used.contains(c.id); ++n)
        c.id = QStringLiteral("controller%1").arg(n);
    c.modelId = models().value(0).id;
    c.port = QStringLiteral("sim");
    addRow(c);
    Q_EMIT idsChanged();
    Q_EMIT edited();
}

void ControllersTable::removeCurrentController()
{
    removeRowAndNotify(currentEditRow());
    Q_EMIT idsChanged();
}

} // namespace stepdeck::ui
