#include "CliCommands.h"
#include "CliText.h"
#include "transport/PortListing.h"
#include <QCoreApplication>
#include <QJsonArray>

namespace stepdeck::cli {

namespace {
struct CommandEntry
{
    // nullptr: a machine command, which runs on a machine also without a file
    // (runsOnTheMachine(), CliMachineRun.cpp) and never on a CliSession.
    Outcome (*run)(CliContext&, QStringList);
    bool needsModel;
    CommandSyntax syntax; // its name and own options (docs/cli.md, "Command options")
};

const QList<CommandOption> kPositioningOptions{{"no-wait"}, {"timeout", "MS"}};

// clang-format off
const CommandEntry kCommands[] = {
    {cmdPorts, false, {"ports", {}}},
    {cmdModels, false, {"models", {}}},
    {cmdMachine, false, {"machine", {}}},
    {cmdParams, true, {"params", {}}},
    {nullptr, true, {"status", {}}},
    {cmdScan, true, {"scan", {{"first", "N"}, {"last", "N"}}}},
    {cmdRecords, true, {"records", {}}},
    {cmdClosedLoop, true, {"closed-loop", {}}},
    {cmdCalibrate, true, {"calibrate", {}}},
    {cmdResetPositionError, true, {"reset-position-error", {}}},
    {cmdSet, true, {"set", {{"no-verify"}}}},
    {cmdGet, true, {"get", {}}},
    {cmdExport, true, {"export", {}}},
    {cmdImport, true, {"import", {{"no-verify"}}}},
    {nullptr, true, {"move", kPositioningOptions + QList<CommandOption>{{"abs"}}}},
    {nullptr, true, {"jog", {{"for", "MS"}}}},
    {cmdHome, true, {"home", kPositioningOptions + QList<CommandOption>{{"simultaneous"},
                                                                        {"closed-loop"}}}},
    {cmdVelocity, true, {"velocity", {{"for", "MS"}}}},
    {cmdFeed, true, {"feed", kPositioningOptions}},
    {nullptr, true, {"stop", {}}},
    {nullptr, true, {"panic", {}}},
    {nullptr, true, {"run", {{"dry-run"}, {"canon"}, {"from-line", "N"}, {"skip-pauses"}, {"reference"},
                             {"optional-stops", "ON|OFF"}, {"block-delete", "ON|OFF"},
                             {"feed-override", "PERCENT"},
                             {"tool-table", "FILE"},
                             {"offsets", "G54:X=N,...;G55:..."}}}},
    {cmdReset, true, {"reset", {}}},
    {cmdSpindle, true, {"spindle", {}}},
    {cmdCoolant, true, {"coolant", {}}},
    {cmdPower, true, {"power", {}}},
    {cmdStore, true, {"store", {{"clear"}}}},
    {cmdOutput, true, {"output", {}}},
    {cmdProgram, true, {"program", {{"title", "TEXT"}, {"erase"}, {"force"}}}},
    {cmdLaserBridge, true, {"laser-bridge", {{"map", "MAP"}, {"scale", "STEPS_PER_UNIT"},
                                             {"home", "DIRECTIONS"}, {"door-input", "N"}}}},
};
// clang-format on

QString defaultText(const ParameterSpec& spec)
{
    if (spec.type == ParameterType::Boolean)
        return spec.defaultValue.toBool() ? QStringLiteral("on") : QStringLiteral("off");
    return spec.defaultValue.toString();
}

QString typeName(ParameterType type)
{
    switch (type) {
    case ParameterType::Integer:
        return QStringLiteral("integer");
    case ParameterType::Boolean:
        return QStringLiteral("boolean");
    case ParameterType::Choice:
        return QStringLiteral("choice");
    }
    return {};
}
} // namespace

Outcome CliContext::connect()
{
    Outcome result = session.connectLink();
    if (!result.ok() || !options.setupDefaults || setupWritten)
        return result;
    setupWritten = true;
    result = writeParameters(*this, unattendedDefaults(*model, axes()));
    if (result.ok())
        result = session.refresh(); // the status words the adapter's rules see are current
    if (!result.ok())
        result.message = CliText::tr("--setup-defaults: %1").arg(result.message);
    return result;
}

ParameterSet unattendedDefaults(const ModelInfo& model, const QList<Axis>& axes)
{
    ParameterSet defaults = schemaDefaults(model, axes);
    for (const ParameterSpec& spec : model.schema.specs()) {
        if (!spec.warning.isEmpty())
            defaults.remove(spec.name);
    }
    // A parameter the model writes only together with one left out (EMIS idle-current with
    // run-current, 9.8) is left out too: the model's rules name the set refused, and the first
    // parameter whose removal makes it acceptable goes (schema order, so always the same).
    if (model.parameterRules) {
        while (!model.parameterRules(model.schema, defaults, {}).isEmpty()) {
            bool dropped = false;
            for (const ParameterSpec& spec : model.schema.specs()) {
                ParameterSet without = defaults;
                if (without.remove(spec.name) &&
                    model.parameterRules(model.schema, without, {}).isEmpty()) {
                    defaults = without;
                    dropped = true;
                    break;
                }
            }
            if (!dropped)
                break; // the write reports why
        }
    }
    return defaults;
}

ParameterSet schemaDefaults(const ModelInfo& model, const QList<Axis>& axes)
{
    ParameterSet set;
    for (const ParameterSpec& spec : model.schema.specs()) {
        if (!spec.writable || !spec.defaultValue.isValid())
            continue;
        ParameterValue value;
        if (spec.perAxis) {
            for (Axis axis : axes)
                value.perAxis.insert(axis, spec.defaultValue);
        } else {
            value.global = spec.defaultValue;
        }
        set.insert(spec.name, value);
    }
    return set;
}

bool canVerify(const ModelInfo& model, const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = model.schema.find(it.key());
        if (!spec || !spec->readable)
            return false;
    }
    return !set.isEmpty();
}

Outcome writeParameters(CliContext& c, const ParameterSet& set, bool verify)
{
    verify = verify && canVerify(*c.model, set);
    return c.session.run([&](ControllerSession& s) { return s.writeParameters(set, verify); });
}

QList<CommandSyntax> commandSyntax()
{
    QList<CommandSyntax> syntax;
    for (const CommandEntry& entry : kCommands)
        syntax << entry.syntax;
    return syntax;
}

Outcome runCommand(CliContext& context)
{
    const QString& name = context.options.command;
    for (const CommandEntry& entry : kCommands) {
        if (name != QLatin1String(entry.syntax.name))
            continue;
        if (!entry.run)
            return Outcome::usage(CliText::tr("%1 runs on the machine, not here").arg(name));
        if (entry.needsModel && !context.model) {
            return Outcome::usage(unknownModelText(context.options.model));
        }
        if (entry.needsModel) {
            // Builds the stack without opening the port: its capabilities follow the axis map.
            if (const Outcome created = context.session.create(); !created.ok())
                return created;
        }
        return entry.run(context, context.options.args);
    }
    return Outcome::usage(unknownCommandText(name, commandSyntax()));
}

Outcome cmdPorts(CliContext& c, QStringList args)
{
    if (!args.isEmpty())
        return Outcome::usage(CliText::tr("ports takes no arguments"));
    QJsonArray list;
    QStringList lines;
    for (const SerialPortListing& port : listSerialPorts()) {
        const QString vidPid = port.vidPid();
        list.append(QJsonObject{{"path", port.path},
                                {"description", port.description},
                                {"manufacturer", port.manufacturer},
                                {"serialNumber", port.serialNumber},
                                {"vidPid", vidPid.isEmpty() ? QJsonValue() : QJsonValue(vidPid)}});
        lines << QStringLiteral("%1  %2  %3%4")
                     .arg(port.path, -16)
                     .arg(port.description.isEmpty() ? CliText::tr("(no description)")
                                                     : port.description)
                     .arg(vidPid.isEmpty() ? CliText::tr("(not USB)") : vidPid)
                     .arg(port.manufacturer.isEmpty() ? QString()
                                                      : QStringLiteral("  ") + port.manufacturer);
    }
    if (c.json()) {
        printJson(QJsonObject{{"ports", list}});
    } else if (lines.isEmpty()) {
        printLine(
            CliText::tr("no serial ports found (pseudo-terminals are never listed: pass their path "
                        "with --port)"));
    } else {
        for (const QString& line : lines)
            printLine(line);
    }
    return Outcome::success();
}

Outcome cmdModels(CliContext& c, QStringList args)
{
    if (!args.isEmpty())
        return Outcome::usage(CliText::tr("models takes no arguments"));
    QJsonArray list;
    for (const ModelInfo& model : models()) {
        QJsonArray axes;
        for (Axis a : model.capabilities.axes)
            axes.append(axisName(a));
        list.append(QJsonObject{{"id", model.id},
                                {"name", model.displayName},
                                {"baudRate", int(model.line.baudRate)},
                                {"axes", axes}});
        if (!c.json())
            printLine(QStringLiteral("%1  %2").arg(model.id, -10).arg(model.displayName));
    }
    if (c.json())
        printJson(QJsonObject{{"models", list}});
    return Outcome::success();
}

Outcome cmdParams(CliContext& c, QStringList args)
{
    if (!args.isEmpty())
        return Outcome::usage(CliText::tr("params takes no arguments"));
    QJsonArray list;
    for (const ParameterSpec& spec : c.model->schema.specs()) {
        // A value the manual gives no unit says so ("(no unit)"), as the setup page does.
        const QString unit = spec.unit.isEmpty() ? spec.unitNote : spec.unit;
        QJsonObject entry{{"name", spec.name},
                          {"label", spec.label},
                          {"group", spec.group},
                          {"unit", spec.unit},
                          {"type", typeName(spec.type)},
                          {"range", ParameterSchema::rangeText(spec)},
                          {"perAxis", spec.perAxis},
                          {"readable", spec.readable},
                          {"writable", spec.writable},
                          {"default", QJsonValue::fromVariant(spec.defaultValue)},
                          {"description", spec.description}};
        if (!spec.unitNote.isEmpty() && spec.unit.isEmpty())
            entry.insert("unitNote",
                         spec.unitNoteDetail.isEmpty() ? spec.unitNote : spec.unitNoteDetail);
        list.append(entry);
        if (c.json())
            continue;
        printLine(
            QStringLiteral("%1  %2  %3  %4  %5  %6")
                .arg(spec.name, -19)
                .arg(spec.perAxis ? CliText::tr("per axis") : CliText::tr("global"), -8)
                .arg(QStringLiteral("%1 %2").arg(ParameterSchema::rangeText(spec), unit).trimmed(),
                     -19)
                .arg(CliText::tr("default %1").arg(defaultText(spec)), -14)
                .arg(spec.readable ? CliText::tr("readable") : CliText::tr("write-only"), -10)
                .arg(spec.label));
    }
    if (c.json())
        printJson(QJsonObject{{"model", c.model->id}, {"parameters", list}});
    return Outcome::success();
}

} // namespace stepdeck::cli
