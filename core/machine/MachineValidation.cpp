// MachineFile::validate: the rules about values, shared by files and the GUI's editor
// (docs/machines.md, "Validation").
#include "MachineFile.h"
#include "model/NearestName.h"
#include "protocols/Registry.h"
#include <QRegularExpression>
#include <QSet>
#include <cmath>

namespace stepdeck::machine {

namespace {

const QStringList& machineAxisNames()
{
    return MachineDescription::axisLetters();
}

class Checker
{
public:
    explicit Checker(MachineFileError* error) : m_error(error) {}

    bool controllers(const MachineDescription& d);
    bool axes(const MachineDescription& d);
    bool spindle(const MachineDescription& d);

private:
    bool fail(const QString& field, const QString& message)
    {
        return MachineFileError::report(m_error, field, message);
    }
    bool controller(const MachineController& c, const QString& path);
    bool addresses(const MachineController& c, const ModelInfo& model, const QString& path);
    bool axis(const MachineDescription& d, const MachineAxis& a, const QString& path);
    bool axisValues(const MachineAxis& a, const ModelInfo& model, const QString& path);

    MachineFileError* m_error;
    QSet<QString> m_axisNames;
    QSet<QString> m_controllerAxes; // "<controller id>/<axis>"
};

QString unitText(AxisUnit unit)
{
    return unitKey(unit);
}

bool Checker::controllers(const MachineDescription& d)
{
    if (d.controllers.isEmpty())
        return fail("controllers", MachineFile::tr("the machine needs at least one controller"));
    QSet<QString> ids;
    for (qsizetype i = 0; i < d.controllers.size(); ++i) {
        const QString path = QStringLiteral("controllers[%1]").arg(i);
        const MachineController& c = d.controllers.at(i);
        if (ids.contains(c.id))
            return fail(path + QStringLiteral(".id"),
                        MachineFile::tr("\"%1\" is used by another controller").arg(c.id));
        ids.insert(c.id);
        if (!controller(c, path))
            return false;
    }
    return true;
}

bool Checker::controller(const MachineController& c, const QString& path)
{
    static const QRegularExpression idPattern(QStringLiteral("^[A-Za-z][A-Za-z0-9_-]{0,23}$"));
    if (!idPattern.match(c.id).hasMatch())
        return fail(path + QStringLiteral(".id"),
                    MachineFile::tr("must be a short name: a letter, then letters, digits, _ or "
                                    "- (at most 24)"));
    const ModelInfo* model = findModel(c.modelId);
    if (!model)
        return fail(path + QStringLiteral(".model"), unknownModelText(c.modelId));
    if (c.port.trimmed().isEmpty())
        return fail(path + QStringLiteral(".port"),
                    MachineFile::tr("must name a serial port, tcp://HOST:PORT or \"sim\""));
    if (c.resetLine && !model->capabilities.resetLine)
        return fail(path + QStringLiteral(".resetLine"),
                    MachineFile::tr("%1 has no reset line").arg(c.modelId));
    return addresses(c, *model, path);
}

bool Checker::addresses(const MachineController& c, const ModelInfo& model, const QString& path)
{
    if (c.busAddresses.isEmpty())
        return true;
    const Capabilities& caps = model.capabilities;
    if (!caps.multiDrive)
        return fail(
            path + QStringLiteral(".axes"),
            MachineFile::tr("%1 has no drives on a bus: leave \"axes\" out").arg(c.modelId));
    QSet<int> used;
    for (auto it = c.busAddresses.cbegin(); it != c.busAddresses.cend(); ++it) {
        const QString field = path + QStringLiteral(".axes.") + c.axisNames.name(it.key());
        if (it.value() < caps.minBusAddress || it.value() > caps.maxBusAddress)
            return fail(field, MachineFile::tr("bus address %1 is outside %2..%3")
                                   .arg(it.value())
                                   .arg(caps.minBusAddress)
                                   .arg(caps.maxBusAddress));
        if (used.contains(it.value()))
            return fail(field,
                        MachineFile::tr("bus address %1 is given to two axes").arg(it.value()));
        used.insert(it.value());
    }
    return true;
}

bool Checker::axes(const MachineDescription& d)
{
    if (d.axes.isEmpty())
        return fail("axes", MachineFile::tr("the machine needs at least one axis"));
    for (qsizetype i = 0; i < d.axes.size(); ++i) {
        if (!axis(d, d.axes.at(i), QStringLiteral("axes[%1]").arg(i)))
            return false;
    }
    return true;
}

bool Checker::axis(const MachineDescription& d, const MachineAxis& a, const QString& path)
{
    // The CLI's machine of a bus names its drives past the ninth by their drive names
    // (DriveAxes::All, never in a file).
    const bool driveName = d.driveNamedAxes && a.name == d.controllerAxisName(a);
    if (!machineAxisNames().contains(a.name) && !driveName)
        return fail(path + QStringLiteral(".name"),
                    MachineFile::tr("must be one of %1").arg(machineAxisNames().join(" ")));
    if (m_axisNames.contains(a.name))
        return fail(path + QStringLiteral(".name"),
                    MachineFile::tr("%1 is used by another axis").arg(a.name));
    m_axisNames.insert(a.name);
    const MachineController* c = d.controller(a.controller);
    if (!c) {
        QStringList ids;
        for (const MachineController& each : d.controllers)
            ids << each.id;
        const QString near = names::nearest(a.controller, ids);
        return fail(path + QStringLiteral(".controller"),
                    near.isEmpty() ? MachineFile::tr("no controller \"%1\" (controllers: %2)")
                                         .arg(a.controller, ids.join(", "))
                                   : MachineFile::tr("no controller \"%1\" (did you mean %2?)")
                                         .arg(a.controller, near));
    }
    const ModelInfo& model = *findModel(c->modelId); // checked by controllers()
    const QList<Axis> have =
        c->busAddresses.isEmpty() ? model.capabilities.axes : c->busAddresses.keys();
    if (!have.contains(a.axis)) {
        QStringList names;
        for (Axis each : have)
            names << c->axisNames.name(each);
        return fail(path + QStringLiteral(".axis"),
                    MachineFile::tr("controller \"%1\" has no axis %2 (it has %3)")
                        .arg(c->id, c->axisNames.name(a.axis), names.join(" ")));
    }
    const QString used = c->id + QLatin1Char('/') + axisName(a.axis);
    if (m_controllerAxes.contains(used))
        return fail(path + QStringLiteral(".axis"),
                    MachineFile::tr("axis %1 of controller \"%2\" already drives another axis")
                        .arg(c->axisNames.name(a.axis), c->id));
    m_controllerAxes.insert(used);
    return axisValues(a, model, path);
}

bool Checker::axisValues(const MachineAxis& a, const ModelInfo& model, const QString& path)
{
    if (!std::isfinite(a.stepsPerUnit) || a.stepsPerUnit <= 0)
        return fail(
            path + QStringLiteral(".stepsPerUnit"),
            MachineFile::tr("must be a decimal greater than 0 (is %1)").arg(a.stepsPerUnit));
    if (a.unit == AxisUnit::Step && a.stepsPerUnit != 1)
        return fail(path + QStringLiteral(".stepsPerUnit"),
                    MachineFile::tr("must be 1 for an axis counted in steps"));
    if (a.softMinimum.has_value() != a.softMaximum.has_value() ||
        (a.hasSoftLimits() && (!std::isfinite(*a.softMinimum) || !std::isfinite(*a.softMaximum) ||
                               *a.softMinimum >= *a.softMaximum)))
        return fail(path + QStringLiteral(".softLimits"),
                    MachineFile::tr("the minimum must be below the maximum"));
    if (a.maxJogSpeed) {
        const double stepsPerSecond = *a.maxJogSpeed * a.stepsPerUnit;
        if (!std::isfinite(*a.maxJogSpeed) || *a.maxJogSpeed <= 0)
            return fail(
                path + QStringLiteral(".maxJogSpeed"),
                MachineFile::tr("must be a speed greater than 0 in %1/s").arg(unitText(a.unit)));
        if (stepsPerSecond > model.capabilities.maxJogSpeed)
            return fail(path + QStringLiteral(".maxJogSpeed"),
                        MachineFile::tr("%1 %2/s is %3 steps/s, above the %4 steps/s %5 can jog")
                            .arg(*a.maxJogSpeed)
                            .arg(unitText(a.unit))
                            .arg(stepsPerSecond)
                            .arg(model.capabilities.maxJogSpeed)
                            .arg(model.id));
    }
    if (a.jogAcceleration && (!std::isfinite(*a.jogAcceleration) || *a.jogAcceleration <= 0 ||
                              !std::isfinite(*a.jogAcceleration * a.stepsPerUnit)))
        return fail(path + QStringLiteral(".jogAcceleration"),
                    MachineFile::tr("must be an acceleration greater than 0 in %1/s\u00b2 (is %2)")
                        .arg(unitText(a.unit))
                        .arg(*a.jogAcceleration));
    if (a.referenceDirection != 0 && !model.capabilities.referenceDirection)
        return fail(path + QStringLiteral(".reference.direction"),
                    MachineFile::tr("%1 chooses the direction of its reference runs itself: leave "
                                    "\"direction\" out")
                        .arg(model.id));
    if (a.referenceDirection != 0 && std::abs(a.referenceDirection) != 1)
        return fail(path + QStringLiteral(".reference.direction"),
                    MachineFile::tr("must be -1 or 1"));
    if (a.referenceOrder < 0 || a.referenceOrder > 99)
        return fail(path + QStringLiteral(".reference.order"),
                    MachineFile::tr("must be a whole number from 0 to 99"));
    return true;
}

// maxRpm maps S onto the range of the controller that switches the spindle: a machine needs
// one, and the scale must be a speed (docs/machines.md, "spindle").
bool Checker::spindle(const MachineDescription& d)
{
    const std::optional<double>& maxRpm = d.spindle.maxRpm;
    if (!maxRpm && !d.spindle.laser)
        return true;
    if (maxRpm && (!std::isfinite(*maxRpm) || *maxRpm <= 0))
        return fail(QStringLiteral("spindle.maxRpm"),
                    MachineFile::tr("must be a speed greater than 0 in rpm (is %1)").arg(*maxRpm));
    for (const MachineController& c : d.controllers)
        if (const ModelInfo* model = findModel(c.modelId); model && model->capabilities.spindle)
            return true;
    return fail(maxRpm ? QStringLiteral("spindle.maxRpm") : QStringLiteral("spindle.laser"),
                MachineFile::tr("no controller of this machine switches a spindle: leave "
                                "\"spindle\" out"));
}

} // namespace

bool MachineFile::validate(const MachineDescription& machine, MachineFileError* error)
{
    if (machine.name.trimmed().isEmpty())
        return MachineFileError::report(error, QStringLiteral("name"),
                                        tr("the machine needs a name"));
    Checker check(error);
    return check.controllers(machine) && check.axes(machine) && check.spindle(machine);
}

} // namespace stepdeck::machine
