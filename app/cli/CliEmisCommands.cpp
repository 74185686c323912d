// Commands for controllers with stored system parameters, digital outputs and input programs
// (EMIS SMC-IC4): store, get of stored values, output, program. The checks of values and
// program commands happen in the adapter (nothing is sent when they fail); these handlers
// parse the arguments and print the results.
#include "CliCommands.h"
#include "model/ModelOperations.h"
#include "model/NumberParsing.h"
#include <QCoreApplication>

namespace stepdeck::cli {

namespace {
struct CliEmis
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::cli::CliEmis)
};

// Decimal only, through NumberParsing like every other number of the CLI: a malformed or
// non-finite number is a usage error (exit 2), a decimal one beyond qint64 is out of range
// (exit 7, as the range checks of the callers).
std::optional<Outcome> parseNumber(const QString& text, qint64* value, const QString& usage)
{
    switch (numbers::parseInteger(text, value)) {
    case NumberError::None:
        return std::nullopt;
    case NumberError::OutOfRange:
        return Outcome::failure(ExitInvalidValue, CliEmis::tr("'%1' is out of range").arg(text));
    case NumberError::Malformed:
    case NumberError::NonFinite:
        break;
    }
    return Outcome::usage(usage);
}

Outcome unsupported(const CliContext& c, const QString& what)
{
    return Outcome::failure(ExitUnsupported, CliEmis::tr("%1 has no %2").arg(c.model->id, what));
}

QString describeEmis(const ParameterSchema& schema, const ParameterSet& set)
{
    QStringList parts;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        if (const ParameterSpec* spec = schema.find(it.key()))
            parts << QStringLiteral("%1=%2").arg(it.key(), schema.formatValue(*spec, it.value()));
    }
    return parts.join(QLatin1Char(' '));
}

Outcome connectAndCall(CliContext& c, const QString& operation, const QVariantMap& args,
                       QVariant* value = nullptr)
{
    Outcome result = c.connect();
    if (!result.ok())
        return result;
    const CommandResult r =
        c.session.call([&](ControllerSession& s) { return s.modelOperation(operation, args); });
    if (r.ok() && value)
        *value = r.value;
    return Outcome::from(r);
}

QStringList toStrings(const QVariant& list)
{
    QStringList out;
    for (const QVariant& v : list.toList())
        out << v.toString();
    return out;
}
} // namespace

Outcome cmdStore(CliContext& c, QStringList args)
{
    if (!c.capabilities().storedParameters)
        return unsupported(c, CliEmis::tr("stored system parameters"));
    if (c.options.flag("clear")) {
        if (!args.isEmpty())
            return Outcome::usage(CliEmis::tr("store --clear takes no other arguments"));
        const Outcome result = connectAndCall(c, operation::kClearStoredParameters, {});
        if (result.ok() && !c.json()) {
            printLine(CliEmis::tr("*PESYS sent: the SMCflex compatibility entry is erased; the "
                                  "other system parameters stay until they are overwritten "
                                  "(manual 9.16)"));
        }
        return result;
    }
    if (args.isEmpty())
        return Outcome::usage(CliEmis::tr("store needs NAME=VALUE[,VALUE,...] or --clear"));
    const ParameterSchema& schema = c.model->schema;
    ParameterSet set;
    for (const QString& arg : args) {
        QString name, error;
        ParameterValue value;
        if (!arg.contains(QLatin1Char('=')))
            return Outcome::usage(CliEmis::tr("expected NAME=VALUE, got '%1'").arg(arg));
        NumberError numberError = NumberError::None;
        if (!schema.parseAssignment(arg, c.axes(), &name, &value, &error, &numberError)) {
            // nan/inf are no value of any parameter: a usage error, as for `set`.
            return Outcome::failure(
                numberError == NumberError::NonFinite ? ExitUsage : ExitInvalidValue, error);
        }
        if (set.contains(name))
            return Outcome::usage(CliEmis::tr("parameter %1 given twice").arg(name));
        set.insert(name, value);
    }
    if (const QString error = schema.validate(set, c.axes()); !error.isEmpty())
        return Outcome::failure(ExitInvalidValue, error);
    QVariant value;
    const Outcome result =
        connectAndCall(c, operation::kStoreParameters,
                       {{operation::arg::kParameters, QVariant::fromValue(set)}}, &value);
    if (result.ok() && !c.json()) {
        printLine(CliEmis::tr("stored as power-on values: %1 (sent: %2)")
                      .arg(describeEmis(schema, set),
                           toStrings(value.toMap().value(QStringLiteral("commands")))
                               .join(QLatin1Char(' '))));
    }
    return result;
}

Outcome cmdGetStored(CliContext& c, QStringList args)
{
    const ParameterSchema& schema = c.model->schema;
    for (const QString& name : args) {
        if (!schema.find(name))
            return Outcome::failure(ExitInvalidValue, schema.unknownNameText(name));
    }
    QVariant value;
    const Outcome result = connectAndCall(c, operation::kReadStoredParameters, {}, &value);
    if (!result.ok())
        return result;
    const QVariantMap map = value.toMap();
    const ParameterSet stored = map.value(QStringLiteral("parameters")).value<ParameterSet>();
    const QStringList wanted = args.isEmpty() ? stored.keys() : args;
    ParameterSet shown;
    QStringList notStored;
    QStringList notSystem;
    for (const QString& name : wanted) {
        if (stored.contains(name))
            shown.insert(name, stored.value(name));
        else if (name == QLatin1String("interpolation") ||
                 name == QLatin1String("reference-offset"))
            notSystem << name;
        else
            notStored << name;
    }
    const QStringList notes = toStrings(map.value(QStringLiteral("notes")));
    if (c.json()) {
        QJsonObject json = schema.toJson(c.model->id, shown);
        json.insert(QStringLiteral("notStored"), QJsonArray::fromStringList(notStored));
        json.insert(QStringLiteral("notes"), QJsonArray::fromStringList(notes));
        printJson(json);
    } else {
        for (auto it = shown.cbegin(); it != shown.cend(); ++it)
            printLine(describeEmis(schema, ParameterSet{{it.key(), it.value()}}));
        for (const QString& name : notStored)
            printLine(CliEmis::tr("%1: not stored (the board uses its default)").arg(name));
        for (const QString& note : notes)
            printLine(CliEmis::tr("note: %1").arg(note));
    }
    if (!notSystem.isEmpty()) {
        return Outcome::failure(ExitUnsupported,
                                CliEmis::tr("%1 cannot be read back: it is no system parameter "
                                            "and the %2 protocol reports no working values")
                                    .arg(notSystem.join(QStringLiteral(", ")), c.model->id));
    }
    return Outcome::success();
}

Outcome cmdOutput(CliContext& c, QStringList args)
{
    const int outputs = c.capabilities().digitalOutputs;
    if (outputs == 0)
        return unsupported(c, CliEmis::tr("switchable outputs"));
    qint64 number = 0;
    const QString usage = CliEmis::tr("output needs N on|off, e.g. `output 3 on`");
    const QString state = args.size() == 2 ? args[1].toLower() : QString();
    if (args.size() != 2 || (state != QLatin1String("on") && state != QLatin1String("off")))
        return Outcome::usage(usage);
    if (const auto failed = parseNumber(args[0], &number, usage))
        return *failed;
    if (number < 1 || number > outputs) {
        return Outcome::failure(
            ExitInvalidValue,
            CliEmis::tr("output %1 does not exist (allowed: 1..%2)").arg(number).arg(outputs));
    }
    const bool on = state == QLatin1String("on");
    const Outcome result =
        connectAndCall(c, operation::kSetOutput,
                       {{operation::arg::kOutput, int(number)}, {operation::arg::kOn, on}});
    if (result.ok() && !c.json())
        printLine(CliEmis::tr("output %1 %2")
                      .arg(number)
                      .arg(on ? CliEmis::tr("on") : CliEmis::tr("off")));
    return result;
}

Outcome cmdProgram(CliContext& c, QStringList args)
{
    if (!c.capabilities().inputPrograms)
        return unsupported(c, CliEmis::tr("input programs"));
    const bool erase = c.options.flag("erase");
    const bool force = c.options.flag("force");
    const std::optional<QString> title = c.options.value("title");
    qint64 input = 0;
    const QString usage = CliEmis::tr("program needs the input number first: `program N "
                                      "--title TEXT COMMAND...` or `program N --erase`");
    if (args.isEmpty())
        return Outcome::usage(usage);
    if (const auto failed = parseNumber(args.first(), &input, usage))
        return *failed;
    args.removeFirst();
    if (erase) {
        if (!args.isEmpty() || title)
            return Outcome::usage(CliEmis::tr("program N --erase takes nothing else"));
        const Outcome result =
            connectAndCall(c, operation::kEraseInputProgram, {{operation::arg::kInput, input}});
        if (result.ok() && !c.json())
            printLine(CliEmis::tr("program of input %1 erased").arg(input));
        return result;
    }
    if (!title)
        return Outcome::usage(CliEmis::tr("program N needs --title TEXT (the program's header)"));
    if (args.isEmpty())
        return Outcome::usage(CliEmis::tr("program N --title TEXT needs at least one command"));
    const Outcome result = connectAndCall(c, operation::kWriteInputProgram,
                                          {{operation::arg::kInput, input},
                                           {operation::arg::kTitle, *title},
                                           {operation::arg::kCommands, args},
                                           {operation::arg::kForce, force}});
    if (result.ok() && !c.json()) {
        printLine(CliEmis::tr("program of input %1 stored: \"%2\", %3 command(s)")
                      .arg(input)
                      .arg(*title)
                      .arg(args.size()));
    }
    return result;
}

} // namespace stepdeck::cli
