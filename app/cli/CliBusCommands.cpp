// Commands for models with several addressed drives on one link (Nanotec, issue 4): `scan`
// lists the drives that answer, `records` reads the 32 stored records of one drive. Both go
// through the generic ControllerSession doors (scanBus, modelOperation); the adapter does the
// protocol work.
#include "CliCommands.h"
#include "CliText.h"
#include "model/ModelOperations.h"
#include <QCoreApplication>
#include <QJsonArray>

namespace stepdeck::cli {

namespace {
constexpr int kScanMsPerAddress = 100; // the adapter waits ~40 ms for a silent address

struct AddressRange
{
    int first = 0;
    int last = 0;
};

// The bus addresses are the model's (Capabilities::minBusAddress..maxBusAddress, e.g. Nanotec
// manual 1.1: 1..254), not a second copy. A model without a bus has none; its --first/--last
// are read against the range of any bus this build knows, so a malformed address is a usage
// error whatever the model, and the scan itself is then refused as unsupported.
AddressRange busAddresses(const Capabilities& caps)
{
    if (caps.multiDrive)
        return {caps.minBusAddress, caps.maxBusAddress};
    AddressRange any{0, -1};
    for (const ModelInfo& model : models()) {
        const Capabilities& c = model.capabilities;
        if (!c.multiDrive)
            continue;
        any.first = any.last < any.first ? c.minBusAddress : qMin(any.first, c.minBusAddress);
        any.last = qMax(any.last, c.maxBusAddress);
    }
    return any;
}

// "--first N" / "--last N" of scan; false with *error set when malformed.
bool readAddress(const CliOptions& options, const char* option, const AddressRange& range,
                 int* value, QString* error)
{
    const std::optional<QString> text = options.value(option);
    if (!text)
        return true;
    if (numbers::parseInt(*text, range.first, range.last, value) != NumberError::None) {
        *error = CliText::tr("scan --%1 needs an address within %2..%3, got '%4'")
                     .arg(QLatin1String(option))
                     .arg(range.first)
                     .arg(range.last)
                     .arg(*text);
        return false;
    }
    return true;
}

QString busValueText(const QVariant& value)
{
    if (value.typeId() == QMetaType::Bool)
        return value.toBool() ? QStringLiteral("on") : QStringLiteral("off");
    return value.toString();
}

// Each drive found under the name --axes gives its address ("axis": "feeder"; issue 32), so a
// technician sees which configured drive answered and which address is a stranger.
QVariantList withDriveNames(const CliOptions& o, QVariantList drives)
{
    for (QVariant& entry : drives) {
        QVariantMap d = entry.toMap();
        const int address = d.value(QStringLiteral("address")).toInt();
        for (auto it = o.axisAddresses.cbegin(); it != o.axisAddresses.cend(); ++it) {
            if (it.value() == address)
                d.insert(QStringLiteral("axis"), o.axisNames.name(it.key()));
        }
        if (o.address && *o.address == address)
            d.insert(QStringLiteral("axis"), axisName(Axis::X)); // --address N: the one drive
        entry = d;
    }
    return drives;
}

// The drives found, one row each; with a bus list (--axes, --address) the name each has there.
void printScan(const CliOptions& o, const QVariantList& drives)
{
    if (o.axisAddresses.isEmpty() && !o.address) {
        // No bus list given: nothing to name the drives by.
        printLine(CliText::tr("Address  Firmware"));
        for (const QVariant& entry : drives) {
            const QVariantMap d = entry.toMap();
            printLine(QStringLiteral("%1  %2")
                          .arg(d.value(QStringLiteral("address")).toInt(), 7)
                          .arg(d.value(QStringLiteral("firmware")).toString()));
        }
        return;
    }
    int width = CliText::tr("Drive").size();
    for (const QVariant& entry : drives)
        width = qMax(width, int(entry.toMap().value(QStringLiteral("axis")).toString().size()));
    printLine(QStringLiteral("%1  %2  %3")
                  .arg(CliText::tr("Address"), 7)
                  .arg(CliText::tr("Drive"), -width)
                  .arg(CliText::tr("Firmware")));
    for (const QVariant& entry : drives) {
        const QVariantMap d = entry.toMap();
        const QString axis = d.value(QStringLiteral("axis")).toString();
        printLine(QStringLiteral("%1  %2  %3")
                      .arg(d.value(QStringLiteral("address")).toInt(), 7)
                      .arg(axis.isEmpty() ? QStringLiteral("-") : axis, -width)
                      .arg(d.value(QStringLiteral("firmware")).toString()));
    }
}
} // namespace

Outcome cmdScan(CliContext& c, QStringList args)
{
    QString error;
    const AddressRange range = busAddresses(c.capabilities());
    int first = range.first;
    int last = range.last;
    const bool ranged = c.options.value("first") || c.options.value("last");
    if (!readAddress(c.options, "first", range, &first, &error) ||
        !readAddress(c.options, "last", range, &last, &error))
        return Outcome::usage(error);
    if (!args.isEmpty())
        return Outcome::usage(
            CliText::tr("scan takes no arguments besides --first N and --last N"));
    if (first > last)
        return Outcome::usage(
            CliText::tr("scan: --first %1 lies after --last %2").arg(first).arg(last));
    if (!c.capabilities().multiDrive) {
        return Outcome::failure(
            ExitUnsupported,
            CliText::tr("%1 has no bus to scan: it is one controller on its own link")
                .arg(c.model->id));
    }
    // No connect(): a scan needs no configured drive; the adapter opens the port for it.
    const int timeoutMs =
        qMax(CliSession::kRequestTimeoutMs, (last - first + 1) * kScanMsPerAddress + 10000);
    const CommandResult result = c.session.call(
        [&](ControllerSession& s) {
            return ranged ? s.modelOperation(operation::kScan, {{operation::arg::kFirst, first},
                                                                {operation::arg::kLast, last}})
                          : s.scanBus();
        },
        timeoutMs);
    if (!result.ok())
        return Outcome::from(result);
    const QVariantList drives = withDriveNames(c.options, result.value.toList());
    if (c.json()) {
        printJson(QJsonArray::fromVariantList(drives));
        return Outcome::success();
    }
    if (drives.isEmpty()) {
        printLine(CliText::tr("no drive answered on addresses %1..%2 of %3")
                      .arg(first)
                      .arg(last)
                      .arg(c.options.port));
        return Outcome::success();
    }
    printScan(c.options, drives);
    return Outcome::success();
}

namespace {
// The one drive a command is for: AXIS, or the only axis there is (--address N).
Outcome driveAxis(const CliContext& c, const QString& command, const QStringList& args, Axis* out)
{
    const QList<Axis> axes = c.axes();
    std::optional<Axis> axis;
    if (args.size() == 1)
        axis = c.options.axisNames.find(args.first()); // "feeder", or a default name
    else if (args.isEmpty() && axes.size() == 1)
        axis = axes.first();
    if (args.size() > 1 || (args.isEmpty() && !axis))
        return Outcome::usage(
            CliText::tr("%1 needs the axis of one drive, e.g. `%1 X`").arg(command));
    if (!axis || !axes.contains(*axis))
        return Outcome::usage(
            CliText::tr("%1: this machine has no axis %2").arg(command, args.first()));
    *out = *axis;
    return Outcome::success();
}
} // namespace

Outcome cmdResetPositionError(CliContext& c, QStringList args)
{
    // Nanotec 'D' (5.14): the position becomes the encoder's, the position error is cleared.
    Axis axis = Axis::X;
    if (const Outcome parsed = driveAxis(c, QStringLiteral("reset-position-error"), args, &axis);
        !parsed.ok())
        return parsed;
    Outcome outcome = c.connect();
    if (!outcome.ok())
        return outcome;
    outcome = c.session.run([&](ControllerSession& s) {
        return s.modelOperation(operation::kResetPositionError,
                                {{operation::arg::kAxis, axisName(axis)}});
    });
    if (outcome.ok() && !c.json())
        printLine(CliText::tr("position error of axis %1 reset: its position is the encoder's")
                      .arg(axisName(axis)));
    return outcome;
}

Outcome cmdRecords(CliContext& c, QStringList args)
{
    Axis axisValue = Axis::X;
    if (const Outcome parsed = driveAxis(c, QStringLiteral("records"), args, &axisValue);
        !parsed.ok())
        return parsed;
    const std::optional<Axis> axis = axisValue;
    Outcome outcome = c.connect();
    if (!outcome.ok())
        return outcome;
    const CommandResult result = c.session.call([&](ControllerSession& s) {
        return s.modelOperation(operation::kReadAllRecords,
                                {{operation::arg::kAxis, axisName(*axis)}});
    });
    if (!result.ok())
        return Outcome::from(result);
    const QVariantList records = result.value.toList();
    if (c.json()) {
        printJson(QJsonArray::fromVariantList(records));
        return Outcome::success();
    }
    for (const QVariant& entry : records) {
        const QVariantMap record = entry.toMap();
        const QVariantMap values = record.value(QStringLiteral("values")).toMap();
        QStringList parts;
        for (auto it = values.cbegin(); it != values.cend(); ++it)
            parts << QStringLiteral("%1=%2").arg(it.key(), busValueText(it.value()));
        printLine(CliText::tr("record %1: %2")
                      .arg(record.value(QStringLiteral("record")).toInt(), 2)
                      .arg(parts.join(QLatin1Char(' '))));
    }
    return Outcome::success();
}

} // namespace stepdeck::cli
