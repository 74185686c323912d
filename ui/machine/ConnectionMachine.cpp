#include "ConnectionMachine.h"
#include <QSettings>

namespace stepdeck::ui {

namespace {

// The soft limits the former Limits… dialog stored, in the controller's steps.
void applyStoredSoftLimits(const QSettings& settings, const QString& modelId,
                           machine::MachineAxis* axis)
{
    const QString p = QStringLiteral("softLimits/%1/%2/").arg(modelId, axisName(axis->axis));
    const bool enabled = settings.value(p + QStringLiteral("enabled"), true).toBool();
    const bool rangeSet = settings.value(p + QStringLiteral("rangeSet"), false).toBool();
    const qint64 minimum = settings.value(p + QStringLiteral("minimum"), 0).toLongLong();
    const qint64 maximum = settings.value(p + QStringLiteral("maximum"), 0).toLongLong();
    if (enabled && rangeSet && maximum > minimum) {
        axis->softMinimum = axis->toUnits(minimum);
        axis->softMaximum = axis->toUnits(maximum);
    }
}

// The units the former Units… dialog stored (0 steps per unit: the controller's count).
void applyStoredUnits(const QSettings& settings, const QString& modelId, machine::MachineAxis* axis)
{
    const QString p = QStringLiteral("units/%1/%2/").arg(modelId, axisName(axis->axis));
    const double stepsPerUnit = settings.value(p + QStringLiteral("stepsPerUnit"), 0.0).toDouble();
    if (!(stepsPerUnit > 0))
        return;
    const QString unit =
        settings.value(p + QStringLiteral("unit"), QStringLiteral("mm")).toString();
    const bool inch = unit == QLatin1String("in");
    axis->unit = unit == QStringLiteral("\u00b0") ? machine::AxisUnit::Degree
                                                  : machine::AxisUnit::Millimetre;
    axis->stepsPerUnit = inch ? stepsPerUnit / 25.4 : stepsPerUnit;
}

} // namespace

machine::MachineDescription connectionMachineOf(const ModelInfo& model, const ConnectionSpec& spec)
{
    QMap<Axis, int> addresses;
    AxisNames names;
    if (model.capabilities.multiDrive) {
        addresses = spec.options.axisAddresses;
        names = spec.options.axisNames;
    }
    machine::MachineDescription d =
        machine::MachineDescription::singleController(model, spec.port, addresses, names);
    if (model.capabilities.resetLine)
        d.controllers.first().resetLine = spec.options.resetLine;
    const QSettings settings;
    for (machine::MachineAxis& a : d.axes) {
        // Default: Z first, then X and Y together, each towards the negative end where most
        // small machines have their switches (a skipped axis keeps its order: the machine
        // references every axis it has).
        const QString r = QStringLiteral("reference/%1/%2/").arg(model.id, a.name);
        a.referenceOrder =
            settings.value(r + QStringLiteral("order"), a.axis == Axis::Z ? 1 : 2).toInt();
        const int direction = settings.value(r + QStringLiteral("direction"), -1).toInt();
        if (model.capabilities.referenceDirection && (direction == -1 || direction == 1))
            a.referenceDirection = direction;
        applyStoredUnits(settings, model.id, &a);
        applyStoredSoftLimits(settings, model.id, &a);
    }
    return d;
}

QString connectionOffsetsKey(const QString& modelId)
{
    return QStringLiteral("connection:") + modelId;
}

} // namespace stepdeck::ui
