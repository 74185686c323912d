// set, get, export, import: all driven by the model's ParameterSchema.
#include "CliCommands.h"
#include "CliText.h"
#include "model/ParameterFile.h"
#include <QCoreApplication>

namespace stepdeck::cli {

namespace {
QString describe(const ParameterSchema& schema, const ParameterSet& set)
{
    QStringList parts;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        if (const ParameterSpec* spec = schema.find(it.key()))
            parts << QStringLiteral("%1=%2").arg(it.key(), schema.formatValue(*spec, it.value()));
    }
    return parts.join(QStringLiteral(" "));
}

// Reads the readable parameters among names; the result is a ParameterSet.
Outcome readBack(CliContext& c, const QStringList& names, ParameterSet* out)
{
    Outcome result = c.connect();
    if (!result.ok())
        return result;
    const CommandResult read =
        c.session.call([&](ControllerSession& s) { return s.readParameters(names); });
    if (!read.ok())
        return Outcome::from(read);
    *out = read.value.value<ParameterSet>();
    return Outcome::success();
}

// A per-axis parameter in a file must cover every axis: the device takes all axes at once.
QString checkComplete(const QList<Axis>& axes, const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        if (!it.value().isPerAxis())
            continue;
        for (Axis axis : axes) {
            if (!it.value().perAxis.contains(axis))
                return CliText::tr("%1 has no value for axis %2").arg(it.key(), axisName(axis));
        }
    }
    return {};
}

// What set/import print after a successful write.
QString writtenText(const ModelInfo& model, const ParameterSet& set, bool verify)
{
    if (!verify)
        return CliText::tr("written (not verified: --no-verify)");
    return canVerify(model, set)
               ? CliText::tr("written and verified")
               : CliText::tr("written (the %1 protocol cannot read these back)").arg(model.id);
}
} // namespace

Outcome cmdSet(CliContext& c, QStringList args)
{
    const bool verify = !c.options.flag("no-verify");
    if (args.isEmpty())
        return Outcome::usage(CliText::tr("set needs NAME=VALUE[,VALUE,...] (see `params`)"));
    const ParameterSchema& schema = c.model->schema;
    const QList<Axis> axes = c.axes();
    ParameterSet set;
    for (const QString& arg : args) {
        if (!arg.contains(QLatin1Char('=')))
            return Outcome::usage(CliText::tr("expected NAME=VALUE, got '%1'").arg(arg));
        QString name;
        ParameterValue value;
        QString error;
        NumberError numberError = NumberError::None;
        if (!schema.parseAssignment(arg, axes, &name, &value, &error, &numberError)) {
            // nan/inf are no value of any parameter: a usage error like anywhere else.
            return Outcome::failure(
                numberError == NumberError::NonFinite ? ExitUsage : ExitInvalidValue, error);
        }
        if (set.contains(name))
            return Outcome::usage(CliText::tr("parameter %1 given twice").arg(name));
        set.insert(name, value);
    }
    if (const QString error = schema.validate(set, axes); !error.isEmpty())
        return Outcome::failure(ExitInvalidValue, error);
    Outcome result = c.connect();
    if (result.ok())
        result = writeParameters(c, set, verify);
    if (result.ok() && !c.json())
        printLine(
            CliText::tr("%1: %2").arg(writtenText(*c.model, set, verify), describe(schema, set)));
    return result;
}

Outcome cmdGet(CliContext& c, QStringList args)
{
    if (c.capabilities().storedParameters)
        return cmdGetStored(c, args); // what the device keeps for power-on
    if (args.isEmpty())
        return Outcome::usage(CliText::tr("get needs one or more parameter names (see `params`)"));
    const ParameterSchema& schema = c.model->schema;
    QStringList readable;
    QStringList writeOnly;
    for (const QString& name : args) {
        const ParameterSpec* spec = schema.find(name);
        if (!spec)
            return Outcome::failure(ExitInvalidValue, schema.unknownNameText(name));
        (spec->readable ? readable : writeOnly) << name;
    }
    if (!readable.isEmpty()) {
        ParameterSet values;
        const Outcome result = readBack(c, readable, &values);
        if (!result.ok())
            return result;
        if (c.json()) {
            printJson(schema.toJson(c.model->id, values));
        } else {
            for (auto it = values.cbegin(); it != values.cend(); ++it)
                printLine(describe(schema, ParameterSet{{it.key(), it.value()}}));
        }
    }
    if (!writeOnly.isEmpty()) {
        return Outcome::failure(
            ExitUnsupported,
            CliText::tr("%1 cannot be read back: the %2 protocol has no command that "
                        "reports it (write-only)")
                .arg(writeOnly.join(QStringLiteral(", ")), c.model->id));
    }
    return Outcome::success();
}

// Export writes every writable parameter: read back from the device where the model can,
// otherwise the schema default ("origin" in the file says which). E-LAB can read nothing
// back, so its export is the default set and needs no device; import accepts exactly this
// format, so export -> edit -> import is the way to keep a machine's setup in a file.
Outcome cmdExport(CliContext& c, QStringList args)
{
    if (args.size() != 1)
        return Outcome::usage(CliText::tr("export needs exactly one FILE"));
    const QString path = args.first();
    ParameterSet set = schemaDefaults(*c.model, c.axes());
    QStringList readable;
    for (const ParameterSpec& spec : c.model->schema.specs()) {
        if (spec.readable && spec.writable)
            readable << spec.name;
    }
    QJsonObject origin;
    for (auto it = set.cbegin(); it != set.cend(); ++it)
        origin.insert(it.key(), QStringLiteral("default"));
    if (!readable.isEmpty()) {
        ParameterSet values;
        const Outcome result = readBack(c, readable, &values);
        if (!result.ok())
            return result;
        for (auto it = values.cbegin(); it != values.cend(); ++it) {
            set.insert(it.key(), it.value());
            origin.insert(it.key(), QStringLiteral("device"));
        }
    }
    QString error;
    if (ParameterFile::save(c.model->schema, c.model->id, set, path, &error,
                            {{QStringLiteral("origin"), origin}}) != ParameterFile::Status::Ok)
        return Outcome::failure(ExitFile, error);
    if (!c.json()) {
        const qsizetype defaults = set.size() - readable.size();
        printLine(
            CliText::tr("exported %1 parameters to %2 (%3 read back, %4 schema defaults: %5 cannot "
                        "report them)")
                .arg(set.size())
                .arg(path)
                .arg(readable.size())
                .arg(defaults)
                .arg(c.model->id));
    }
    return Outcome::success();
}

Outcome cmdImport(CliContext& c, QStringList args)
{
    const bool verify = !c.options.flag("no-verify");
    if (args.size() != 1)
        return Outcome::usage(CliText::tr("import needs exactly one FILE"));
    const QString path = args.first();
    // Everything is validated before the first byte goes out: a broken file changes nothing.
    ParameterSet set;
    QString error;
    switch (ParameterFile::load(c.model->schema, c.model->id, c.axes(), path, &set, &error)) {
    case ParameterFile::Status::Ok:
        break;
    case ParameterFile::Status::FileError:
    case ParameterFile::Status::NotJson:
        return Outcome::failure(ExitFile, error);
    case ParameterFile::Status::Invalid:
        return Outcome::failure(ExitInvalidValue, error);
    }
    if (error = checkComplete(c.axes(), set); !error.isEmpty())
        return Outcome::failure(ExitInvalidValue, CliText::tr("%1 refused: %2").arg(path, error));
    if (set.isEmpty())
        return Outcome::failure(ExitInvalidValue,
                                CliText::tr("%1 refused: no parameters in it").arg(path));
    Outcome result = c.connect();
    if (result.ok())
        result = writeParameters(c, set, verify);
    if (result.ok() && !c.json()) {
        printLine(CliText::tr("imported %1 parameters from %2: %3")
                      .arg(set.size())
                      .arg(path, writtenText(*c.model, set, verify)));
    }
    return result;
}

} // namespace stepdeck::cli
