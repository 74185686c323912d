#include "MachineDescription.h"
#include "model/ModelInfo.h"
#include <QJsonArray>
#include <cmath>

namespace stepdeck::machine {

namespace {
struct UnitWord
{
    AxisUnit unit;
    const char* key;
};
constexpr UnitWord kUnitWords[] = {
    {AxisUnit::Millimetre, "mm"},
    {AxisUnit::Degree, "deg"},
    {AxisUnit::Step, "steps"},
};

QJsonObject controllerJson(const MachineController& c)
{
    QJsonObject o{{"id", c.id}, {"model", c.modelId}, {"port", c.port}};
    if (!c.busAddresses.isEmpty()) {
        QJsonArray list; // in axis order, each axis by its name (version 2)
        for (const NamedAddress& e : namedAddresses(c.busAddresses, c.axisNames))
            list.append(QJsonObject{{"name", e.name}, {"address", e.address}});
        o.insert("axes", list);
    }
    if (c.resetLine)
        o.insert("resetLine", resetLineName(*c.resetLine));
    if (!c.setupFile.isEmpty())
        o.insert("setup", c.setupFile);
    return o;
}

QJsonObject axisJson(const MachineAxis& a, const AxisNames& names)
{
    QJsonObject o{{"name", a.name},
                  {"controller", a.controller},
                  {"axis", names.name(a.axis)},
                  {"unit", unitKey(a.unit)},
                  {"stepsPerUnit", a.stepsPerUnit}};
    if (a.invert)
        o.insert("invert", true);
    if (a.hasSoftLimits())
        o.insert("softLimits", QJsonArray{*a.softMinimum, *a.softMaximum});
    if (a.maxJogSpeed)
        o.insert("maxJogSpeed", *a.maxJogSpeed);
    if (a.jogAcceleration)
        o.insert("jogAcceleration", *a.jogAcceleration);
    QJsonObject reference{{"order", a.referenceOrder}};
    if (a.referenceDirection != 0)
        reference.insert("direction", a.referenceDirection);
    o.insert("reference", reference);
    return o;
}
} // namespace

QString unitKey(AxisUnit unit)
{
    for (const UnitWord& w : kUnitWords) {
        if (w.unit == unit)
            return QString::fromLatin1(w.key);
    }
    return {};
}

std::optional<AxisUnit> unitFromKey(const QString& key)
{
    for (const UnitWord& w : kUnitWords) {
        if (key == QLatin1String(w.key))
            return w.unit;
    }
    return std::nullopt;
}

QString limitPolicyKey(LimitPolicy policy)
{
    return policy == LimitPolicy::Refuse ? QStringLiteral("refuse") : QStringLiteral("clamp");
}

std::optional<LimitPolicy> limitPolicyFromKey(const QString& key)
{
    if (key == QLatin1String("clamp"))
        return LimitPolicy::Clamp;
    if (key == QLatin1String("refuse"))
        return LimitPolicy::Refuse;
    return std::nullopt;
}

QString toolLengthKey(ToolLength mode)
{
    return mode == ToolLength::TouchOff ? QStringLiteral("touchOff") : QStringLiteral("table");
}

std::optional<ToolLength> toolLengthFromKey(const QString& key)
{
    if (key == QLatin1String("table"))
        return ToolLength::Table;
    if (key == QLatin1String("touchOff"))
        return ToolLength::TouchOff;
    return std::nullopt;
}

qint64 MachineAxis::toSteps(double units) const
{
    // Clamped far beyond any controller's range (which the caller checks), so that a wild
    // value cannot overflow the conversion.
    constexpr double kLimit = 1e15;
    const double product = units * stepsPerUnit;
    const double exact = std::isfinite(product) ? qBound(-kLimit, product, kLimit) : 0.0;
    const qint64 steps = std::llround(exact);
    return invert ? -steps : steps;
}

double MachineAxis::toUnits(qint64 steps) const
{
    const double units = double(invert ? -steps : steps) / stepsPerUnit;
    return units == 0 ? 0.0 : units; // never "-0.000"
}

double MachineAxis::toStepRate(double unitsPerSecond) const
{
    const double rate = unitsPerSecond * stepsPerUnit;
    return invert ? -rate : rate;
}

double MachineAxis::topJogSpeed(double controllerCeilingStepsPerS) const
{
    return maxJogSpeed ? *maxJogSpeed : controllerCeilingStepsPerS / stepsPerUnit;
}

std::optional<double> MachineAxis::effectiveJogAcceleration(double controllerCeilingStepsPerS) const
{
    if (jogAcceleration || unit == AxisUnit::Step)
        return jogAcceleration;
    // v^2 = 2 a s: from the top speed to standstill within s = 1 unit.
    const double top = topJogSpeed(controllerCeilingStepsPerS);
    return top * top / 2.0;
}

double MachineDescription::jogRampAcceleration(const QString& controllerId,
                                               double controllerCeilingStepsPerS) const
{
    // One ramp brakes every axis of the controller, in steps/s^2. Axis i at v units/s stops
    // within v^2 x stepsPerUnit / (2 A) units on a ramp of A steps/s^2, which is within its own
    // v^2 / (2 a_i) only while A >= a_i x stepsPerUnit. So the steepest axis sets the ramp:
    // the largest a_i x stepsPerUnit is the one that keeps every axis within its stopping
    // distance (the smallest would let the steeper axes coast past theirs). The gentler axes
    // then brake harder than their own jogAcceleration; a machine whose axes cannot take that
    // puts them on separate controllers or gives them the same stopping distance.
    double steepest = 0;
    for (const MachineAxis& a : axes) {
        if (a.controller != controllerId)
            continue;
        if (const auto acc = a.effectiveJogAcceleration(controllerCeilingStepsPerS))
            steepest = qMax(steepest, *acc * a.stepsPerUnit);
    }
    return steepest;
}

const MachineController* MachineDescription::controller(const QString& id) const
{
    for (const MachineController& c : controllers) {
        if (c.id == id)
            return &c;
    }
    return nullptr;
}

const MachineAxis* MachineDescription::axis(const QString& axisNameInMachine) const
{
    for (const MachineAxis& a : axes) {
        if (a.name == axisNameInMachine)
            return &a;
    }
    return nullptr;
}

const MachineAxis* MachineDescription::findAxis(const QString& wanted) const
{
    if (const MachineAxis* exact = axis(wanted))
        return exact;
    const MachineAxis* found = nullptr;
    for (const MachineAxis& a : axes) {
        if (a.name.compare(wanted, Qt::CaseInsensitive) == 0)
            return &a;
        if (controllerAxisName(a).compare(wanted, Qt::CaseInsensitive) == 0) {
            if (found)
                return nullptr; // two controllers give an axis that name
            found = &a;
        }
    }
    return found;
}

QString MachineDescription::controllerAxisName(const MachineAxis& a) const
{
    const MachineController* c = controller(a.controller);
    return c ? c->axisNames.name(a.axis) : axisName(a.axis);
}

int MachineDescription::axisIndex(const QString& axisNameInMachine) const
{
    for (int i = 0; i < axes.size(); ++i) {
        if (axes.at(i).name == axisNameInMachine)
            return i;
    }
    return -1;
}

QList<QList<const MachineAxis*>> MachineDescription::referenceGroups() const
{
    QMap<int, QList<const MachineAxis*>> byOrder;
    for (const MachineAxis& a : axes)
        byOrder[a.referenceOrder].append(&a);
    return byOrder.values();
}

const QStringList& MachineDescription::axisLetters()
{
    static const QStringList letters = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};
    return letters;
}

MachineDescription MachineDescription::singleController(const ModelInfo& model, const QString& port,
                                                        const QMap<Axis, int>& addresses,
                                                        const AxisNames& names, DriveAxes drives)
{
    MachineDescription d;
    d.name = model.displayName;
    d.driveNamedAxes = drives == DriveAxes::All;
    MachineController c;
    c.id = model.id;
    c.modelId = model.id;
    c.port = port;
    c.busAddresses = addresses;
    c.axisNames = names;
    d.controllers << c;
    const QList<Axis> axes = addresses.isEmpty() ? model.capabilities.axes : addresses.keys();
    QStringList free = axisLetters();
    for (Axis axis : axes) {
        if (free.contains(axisName(axis)))
            free.removeOne(axisName(axis));
    }
    for (Axis axis : axes) {
        MachineAxis a;
        a.name = axisLetters().contains(axisName(axis)) ? axisName(axis) : free.value(0);
        if (a.name.isEmpty() && drives == DriveAxes::Letters)
            break; // nine machine axes at most
        if (a.name.isEmpty())
            a.name = names.name(axis);
        free.removeOne(a.name);
        a.controller = c.id;
        a.axis = axis;
        d.axes << a;
    }
    return d;
}

QJsonObject MachineDescription::toJson() const
{
    QJsonArray controllerList;
    for (const MachineController& c : controllers)
        controllerList.append(controllerJson(c));
    QJsonArray axisList;
    for (const MachineAxis& a : axes)
        axisList.append(axisJson(a, controller(a.controller) ? controller(a.controller)->axisNames
                                                             : AxisNames()));
    QJsonObject o{{"format", "stepdeck-machine"},
                  {"version", 2},
                  {"name", name},
                  {"controllers", controllerList},
                  {"axes", axisList}};
    QJsonObject spindleObject; // optional: a machine without it writes the file older readers read
    if (spindle.maxRpm)
        spindleObject.insert("maxRpm", *spindle.maxRpm);
    if (spindle.laser)
        spindleObject.insert("laser", true);
    if (!spindleObject.isEmpty())
        o.insert("spindle", spindleObject);
    if (!crossControllerFeed) // optional as well: written only where it differs from the default
        o.insert("crossControllerFeed", false);
    if (limits != LimitPolicy::Clamp) // the default: files before issue 50 stay as they were
        o.insert("limits", limitPolicyKey(limits));
    if (!subroutineFolder.isEmpty())
        o.insert("subroutineFolder", subroutineFolder);
    if (toolLength != ToolLength::Table) // the default is left out, as crossControllerFeed
        o.insert("toolLength", toolLengthKey(toolLength));
    return o;
}

bool operator==(const MachineController& a, const MachineController& b)
{
    return a.id == b.id && a.modelId == b.modelId && a.port == b.port &&
           a.busAddresses == b.busAddresses && a.axisNames == b.axisNames &&
           a.resetLine == b.resetLine && a.setupFile == b.setupFile;
}

bool operator==(const MachineAxis& a, const MachineAxis& b)
{
    return a.name == b.name && a.controller == b.controller && a.axis == b.axis &&
           a.unit == b.unit && a.stepsPerUnit == b.stepsPerUnit && a.invert == b.invert &&
           a.softMinimum == b.softMinimum && a.softMaximum == b.softMaximum &&
           a.maxJogSpeed == b.maxJogSpeed && a.jogAcceleration == b.jogAcceleration &&
           a.referenceDirection == b.referenceDirection && a.referenceOrder == b.referenceOrder;
}

bool operator==(const MachineSpindle& a, const MachineSpindle& b)
{
    return a.maxRpm == b.maxRpm && a.laser == b.laser;
}

bool operator==(const MachineDescription& a, const MachineDescription& b)
{
    return a.name == b.name && a.controllers == b.controllers && a.axes == b.axes &&
           a.spindle == b.spindle && a.crossControllerFeed == b.crossControllerFeed &&
           a.toolLength == b.toolLength && a.limits == b.limits &&
           a.subroutineFolder == b.subroutineFolder && a.driveNamedAxes == b.driveNamedAxes;
}

} // namespace stepdeck::machine
