#include "AxesTable.h"
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QLocale>
#include <QSet>
#include <QSpinBox>
#include <algorithm>

namespace stepdeck::ui {

using machine::AxisUnit;
using machine::MachineAxis;
using machine::MachineFileError;

namespace {
const QStringList kNames = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};

QStringList keys()
{
    return {"name",
            "controller",
            "axis",
            "unit",
            "stepsPerUnit",
            "invert",
            "softMin",
            "softMax",
            "maxJogSpeed",
            "jogAcceleration",
            "reference.direction",
            "reference.order"};
}

// The shortest text that reads back to the same double: an unchanged cell saves unchanged.
QString numberText(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

QString optionalText(const std::optional<double>& value)
{
    return value ? numberText(*value) : QString();
}

// The first controller axis that drives no machine axis yet ("<id>/<axis>" in used), in the
// order of the controllers; false (and nothing changed) when every one is taken.
bool firstFreeAxis(const QStringList& ids, const QMap<QString, ControllerAxes>& axes,
                   const QSet<QString>& used, QString* id, Axis* axis)
{
    for (const QString& each : ids) {
        for (Axis candidate : axes.value(each).axes) {
            if (!used.contains(each + QLatin1Char('/') + axisName(candidate))) {
                *id = each;
                *axis = candidate;
                return true;
            }
        }
    }
    return false;
}

template <typename T> T* as(QWidget* w)
{
    return qobject_cast<T*>(w);
}
} // namespace

AxesTable::AxesTable(QWidget* parent)
    : EditorTable(keys(),
                  {tr("Name"), tr("Controller"), tr("Axis"), tr("Unit"), tr("Steps/unit"),
                   tr("Invert"), tr("Min"), tr("Max"), tr("Max jog/s"), tr("Jog accel./s\u00b2"),
                   tr("Ref. direction"), tr("Ref. order")},
                  6, parent)
{
    setObjectName(QStringLiteral("axesTable"));
    horizontalHeaderItem(columnOf("softMin"))->setToolTip(tr("Soft limit minimum (optional)"));
    horizontalHeaderItem(columnOf("softMax"))->setToolTip(tr("Soft limit maximum (optional)"));
    horizontalHeaderItem(columnOf("maxJogSpeed"))
        ->setToolTip(tr("Jog speed ceiling in unit/s (optional)"));
    horizontalHeaderItem(columnOf("jogAcceleration"))
        ->setToolTip(tr("Jog acceleration in unit/s\u00b2 (optional; empty: a release from the "
                        "max jog speed stops within 1 mm or 1 deg)"));
    horizontalHeaderItem(columnOf("reference.order"))
        ->setToolTip(tr("Axes with a lower order are referenced first"));
}

void AxesTable::setAxes(const QList<MachineAxis>& axes)
{
    setRowCount(0);
    for (const MachineAxis& a : axes)
        addRow(a);
}

QList<QWidget*> AxesTable::cells(int row, const QString& key) const
{
    if (key == QLatin1String("softLimits"))
        return EditorTable::cells(row, "softMin") + EditorTable::cells(row, "softMax");
    return EditorTable::cells(row, key);
}

void AxesTable::addRow(const MachineAxis& a)
{
    const int row = rowCount();
    insertRow(row);
    QComboBox* name = addComboCell(row, "name", 50);
    name->addItems(kNames);
    name->setCurrentIndex(int(kNames.indexOf(a.name)));
    QComboBox* controller = addComboCell(row, "controller", 110);
    controller->addItems(m_controllerIds);
    if (!m_controllerIds.contains(a.controller))
        controller->addItem(a.controller);
    controller->setCurrentText(a.controller);
    QComboBox* axis = addComboCell(row, "axis", 50);
    axis->addItem(m_controllerAxes.value(a.controller).names.name(a.axis), a.axis.index());
    refreshAxisChoices(row);
    connect(controller, &QComboBox::currentIndexChanged, this,
            [this, controller] { refreshAxisChoices(rowOf(controller, "controller")); });
    for (QComboBox* combo : {name, controller, axis})
        connect(combo, &QComboBox::currentIndexChanged, this, &EditorTable::edited);
    // A choice no longer offered leaves the list once another is chosen.
    connect(axis, &QComboBox::currentIndexChanged, this,
            [this, axis] { refreshAxisChoices(rowOf(axis, "axis")); });
    addUnitCells(row, a);
    addReferenceCells(row, a);
}

void AxesTable::addUnitCells(int row, const MachineAxis& a)
{
    QComboBox* unit = addComboCell(row, "unit", 70);
    for (AxisUnit each : {AxisUnit::Millimetre, AxisUnit::Degree, AxisUnit::Step})
        unit->addItem(machine::unitKey(each), int(each));
    unit->setCurrentIndex(unit->findData(int(a.unit)));
    QLineEdit* perUnit = addLineCell(row, "stepsPerUnit", numberText(a.stepsPerUnit), 90);
    connect(unit, &QComboBox::currentIndexChanged, this, [this, unit, perUnit] {
        if (unit->currentData().toInt() == int(AxisUnit::Step))
            perUnit->setText(QStringLiteral("1")); // the only value steps can have
        Q_EMIT edited();
    });
    auto* invert = new QCheckBox;
    invert->setChecked(a.invert);
    invert->setToolTip(tr("A positive machine move is a negative controller move"));
    connect(invert, &QCheckBox::toggled, this, &EditorTable::edited);
    setCellWidget(row, columnOf("invert"), invert);
    addLineCell(row, "softMin", optionalText(a.softMinimum), 70);
    addLineCell(row, "softMax", optionalText(a.softMaximum), 70);
    addLineCell(row, "maxJogSpeed", optionalText(a.maxJogSpeed), 80);
    addLineCell(row, "jogAcceleration", optionalText(a.jogAcceleration), 80);
}

void AxesTable::addReferenceCells(int row, const MachineAxis& a)
{
    QComboBox* direction = addComboCell(row, "reference.direction", 100);
    direction->addItem(tr("default"), 0);
    direction->addItem(QStringLiteral("\u2212"), -1);
    direction->addItem(QStringLiteral("+"), 1);
    direction->setCurrentIndex(qMax(0, direction->findData(a.referenceDirection)));
    connect(direction, &QComboBox::currentIndexChanged, this, &EditorTable::edited);
    auto* order = new QSpinBox;
    order->setFrame(false);
    order->setRange(0, 99);
    order->setValue(a.referenceOrder);
    connect(order, &QSpinBox::valueChanged, this, &EditorTable::edited);
    setCellWidget(row, columnOf("reference.order"), order);
    fitColumn("reference.order", 70);
}

bool AxesTable::read(QList<MachineAxis>* out, MachineFileError* error) const
{
    out->clear();
    for (int r = 0; r < rowCount(); ++r) {
        MachineAxis a;
        if (!readRow(r, &a, error))
            return false;
        *out << a;
    }
    return true;
}

bool AxesTable::readRow(int r, MachineAxis* a, MachineFileError* error) const
{
    const QString path = QStringLiteral("axes[%1].").arg(r);
    a->name = as<QComboBox>(cell(r, "name"))->currentText();
    a->controller = as<QComboBox>(cell(r, "controller"))->currentText();
    a->axis =
        Axis::fromIndex(as<QComboBox>(cell(r, "axis"))->currentData().toInt()).value_or(Axis::X);
    a->unit = AxisUnit(as<QComboBox>(cell(r, "unit"))->currentData().toInt());
    a->invert = as<QCheckBox>(cell(r, "invert"))->isChecked();
    a->referenceDirection = as<QComboBox>(cell(r, "reference.direction"))->currentData().toInt();
    a->referenceOrder = as<QSpinBox>(cell(r, "reference.order"))->value();
    std::optional<double> perUnit;
    if (!readDecimal(as<QLineEdit>(cell(r, "stepsPerUnit")), path + "stepsPerUnit", false, &perUnit,
                     error))
        return false;
    a->stepsPerUnit = *perUnit;
    const QString limits = path + QStringLiteral("softLimits");
    return readDecimal(as<QLineEdit>(cell(r, "softMin")), limits, true, &a->softMinimum, error) &&
           readDecimal(as<QLineEdit>(cell(r, "softMax")), limits, true, &a->softMaximum, error) &&
           readDecimal(as<QLineEdit>(cell(r, "maxJogSpeed")), path + "maxJogSpeed", true,
                       &a->maxJogSpeed, error) &&
           readDecimal(as<QLineEdit>(cell(r, "jogAcceleration")), path + "jogAcceleration", true,
                       &a->jogAcceleration, error);
}

void AxesTable::setControllerIds(const QStringList& ids)
{
    m_controllerIds = ids;
    for (int r = 0; r < rowCount(); ++r) {
        auto* combo = as<QComboBox>(cell(r, "controller"));
        const QString current = combo->currentText();
        const QSignalBlocker block(combo);
        combo->clear();
        combo->addItems(ids);
        if (!ids.contains(current))
            combo->addItem(current); // kept: the validator names it
        combo->setCurrentText(current);
    }
}

void AxesTable::setControllerAxes(const QMap<QString, ControllerAxes>& axes)
{
    m_controllerAxes = axes;
    for (int r = 0; r < rowCount(); ++r)
        refreshAxisChoices(r);
}

void AxesTable::refreshAxisChoices(int row)
{
    auto* combo = as<QComboBox>(cell(row, "axis"));
    if (!combo)
        return;
    const QString controller = as<QComboBox>(cell(row, "controller"))->currentText();
    const ControllerAxes known =
        m_controllerAxes.value(controller, ControllerAxes{letterAxes(), {}});
    const QList<Axis>& offered = known.axes;
    const int current = combo->currentData().toInt();
    QList<int> wanted;
    for (Axis each : offered)
        wanted << each.index();
    if (Axis::fromIndex(current) && !wanted.contains(current)) {
        wanted << current; // the file's choice stays visible, even if the controller lacks it
        std::sort(wanted.begin(), wanted.end());
    }
    QStringList wantedTexts;
    for (int each : wanted)
        wantedTexts << known.names.name(Axis::at(each));
    QList<int> shown;
    QStringList shownTexts;
    for (int i = 0; i < combo->count(); ++i) {
        shown << combo->itemData(i).toInt();
        shownTexts << combo->itemText(i);
    }
    if (shown == wanted && shownTexts == wantedTexts)
        return; // unchanged: an open list stays as it is
    const QSignalBlocker block(combo);
    combo->clear();
    for (qsizetype i = 0; i < wanted.size(); ++i)
        combo->addItem(wantedTexts.at(i), wanted.at(i));
    combo->setCurrentIndex(combo->findData(current));
}

void AxesTable::renameController(const QString& from, const QString& to)
{
    for (int r = 0; r < rowCount(); ++r) {
        auto* combo = as<QComboBox>(cell(r, "controller"));
        if (combo->currentText() == from) {
            const QSignalBlocker block(combo);
            combo->setItemText(combo->currentIndex(), to);
        }
    }
}

void AxesTable::addAxis()
{
    MachineAxis a;
    QStringList names;
    QSet<QString> used; // "<controller>/<axis>"
    for (int r = 0; r < rowCount(); ++r) {
        names << as<QComboBox>(cell(r, "name"))->currentText();
        used << as<QComboBox>(cell(r, "controller"))->currentText() + QLatin1Char('/') +
                    as<QComboBox>(cell(r, "axis"))->currentText();
    }
    const auto freeName = std::find_if(kNames.cbegin(), kNames.cend(),
                                       [&](const QString& n) { return !names.contains(n); });
    if (freeName == kNames.cend())
        return; // all nine names are in use
    a.name = *freeName;
    a.controller = m_controllerIds.value(0);
    firstFreeAxis(m_controllerIds, m_controllerAxes, used, &a.controller, &a.axis);
    addRow(a); // with every controller axis taken, the validator says so
    Q_EMIT edited();
}

void AxesTable::removeCurrentAxis()
{
    removeRowAndNotify(currentEditRow());
}

} // namespace stepdeck::ui
