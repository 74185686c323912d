#include "CliOutput.h"
#include "CliText.h"
#include "protocols/Registry.h"
#include <QCoreApplication>
#include <QJsonDocument>
#include <cstdio>

namespace stepdeck::cli {

namespace {
QString yesNo(bool value)
{
    return value ? CliText::tr("yes") : CliText::tr("no");
}

QString positionText(const AxisStatus& axis)
{
    // Host-tracked positions: without a reference run they count from this session's start;
    // jog and velocity moves are integrated from the commanded rates.
    QStringList marks;
    if (!axis.positionKnown)
        marks << CliText::tr("unknown: not referenced");
    if (axis.positionEstimated)
        marks << CliText::tr("estimated");
    const QString text = QString::number(axis.position);
    return marks.isEmpty() ? text
                           : QStringLiteral("%1 (%2)").arg(text, marks.join(QStringLiteral("; ")));
}

// A status word in hex with the manual's names of its set bits ("0x0080 tmInvSetup"); any
// other raw value as it is.
QString rawValueText(const QString& key, const QVariant& value, const QList<StatusWordInfo>& words)
{
    for (const StatusWordInfo& word : words) {
        if (word.key != key)
            continue;
        const qulonglong bits = value.toULongLong();
        QStringList set;
        for (const StatusBitInfo& bit : word.bits) {
            if (bits & (1ull << bit.bit))
                set << bit.name;
        }
        const QString hex =
            QStringLiteral("0x%1").arg(bits, (word.width + 3) / 4, 16, QLatin1Char('0'));
        return set.isEmpty() ? hex : QStringLiteral("%1 (%2)").arg(hex, set.join(QLatin1Char(' ')));
    }
    return value.toString();
}
} // namespace

int exitCodeFor(ErrorKind kind)
{
    switch (kind) {
    case ErrorKind::None:
        return ExitOk;
    case ErrorKind::Refused:
        return ExitRefused;
    case ErrorKind::Nak:
        return ExitNak;
    case ErrorKind::Timeout:
        return ExitTimeout;
    case ErrorKind::LinkDown:
        return ExitLinkDown;
    case ErrorKind::InvalidValue:
        return ExitInvalidValue;
    case ErrorKind::Unsupported:
        return ExitUnsupported;
    case ErrorKind::Protocol:
        return ExitProtocol;
    case ErrorKind::Cancelled:
        return ExitCancelled;
    case ErrorKind::VerifyFailed:
        return ExitVerifyFailed;
    }
    return ExitFailure;
}

QString exitCodeHelp()
{
    return CliText::tr(
        "Exit codes:\n"
        "   0  success\n"
        "   1  other failure\n"
        "   2  usage: unknown command or option, malformed arguments, unknown model\n"
        "   3  refused: not sent, the manual forbids it now (limit switch, not idle,\n"
        "      setup incomplete, position unknown, ...)\n"
        "   4  NAK: the device refused the command; stderr names the decoded status bits\n"
        "   5  timeout: no reply in time\n"
        "   6  link down: could not connect, or the link was lost (also a controller\n"
        "      that stopped answering during any command)\n"
        "   7  invalid value: out of range or wrong type (names parameter and range);\n"
        "      also a parameter file whose content does not validate; nothing was sent\n"
        "   8  unsupported: the model cannot do this (e.g. read a parameter back)\n"
        "   9  protocol: malformed reply from the device\n"
        "  10  cancelled: dropped by stop, panic or disconnect before it was sent\n"
        "  11  verify failed: written, but the read-back differs\n"
        "  12  file: cannot read or write the file, or it is not JSON\n"
        "  13  motion aborted: a move ended on a limit switch or an emergency stop\n"
        " 130  interrupted (SIGINT/SIGTERM/SIGHUP): motion was stopped (a ramped stop;\n"
        "      the message says whether the controller acknowledged it), then the CLI\n"
        "      quit\n");
}

Outcome Outcome::from(const CommandResult& result)
{
    if (result.ok())
        return success();
    return failure(exitCodeFor(result.error), result.message);
}

void printLine(const QString& line)
{
    const QByteArray bytes = line.toUtf8();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

void printJson(const QJsonObject& object)
{
    printLine(QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact)));
}

void printJson(const QJsonArray& array)
{
    printLine(QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Compact)));
}

void printError(const QString& message)
{
    QString line = message.simplified();
    if (line.isEmpty())
        line = CliText::tr("failed");
    const QByteArray bytes = QStringLiteral("stepdeck-cli: %1\n").arg(line).toUtf8();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stderr);
    std::fflush(stderr);
}

namespace {
QString driveLabel(const DriveStatus& drive, const AxisNames& names)
{
    QStringList axes;
    for (Axis a : drive.axes)
        axes << names.name(a);
    return axes.isEmpty() ? CliText::tr("drive %1").arg(drive.address)
                          : CliText::tr("drive %1 (axis %2)")
                                .arg(drive.address)
                                .arg(axes.join(QLatin1Char(',')));
}

// "Drives: 2 of 3 answering; silent: drive 2 (axis Y)" and one row per drive.
QStringList driveLines(const QList<DriveStatus>& drives, const AxisNames& names)
{
    QStringList silent;
    int width = 4; // "Axes"
    for (const DriveStatus& d : drives) {
        if (!d.responding)
            silent << driveLabel(d, names);
        QStringList axes;
        for (Axis a : d.axes)
            axes << names.name(a);
        width = qMax(width, int(axes.join(QLatin1Char(',')).size()));
    }
    QStringList lines;
    lines << (silent.isEmpty() ? CliText::tr("Drives:       %1 answering").arg(drives.size())
                               : CliText::tr("Drives:       %1 of %2 answering; NOT ANSWERING: %3")
                                     .arg(drives.size() - silent.size())
                                     .arg(drives.size())
                                     .arg(silent.join(QStringLiteral(", "))));
    lines << QStringLiteral("%1  %2  %3")
                 .arg(CliText::tr("Drive"), -5)
                 .arg(CliText::tr("Axes"), -width)
                 .arg(CliText::tr("Responding  Firmware                    State"));
    for (const DriveStatus& d : drives) {
        QStringList axes;
        for (Axis a : d.axes)
            axes << names.name(a);
        lines << QStringLiteral("%1  %2  %3  %4  %5")
                     .arg(d.address, -5)
                     .arg(axes.join(QLatin1Char(',')), -width)
                     .arg(d.responding ? CliText::tr("yes") : CliText::tr("NO"), -10)
                     .arg(d.firmware.isEmpty() ? QStringLiteral("-") : d.firmware, -26)
                     .arg(d.detail.isEmpty() ? QStringLiteral("-") : d.detail);
    }
    return lines;
}
} // namespace

QString formatStatus(const MachineStatus& status, const ModelInfo& model,
                     const Capabilities& capabilities, const QString& port,
                     const QString& linkState, const AxisNames& names)
{
    QStringList machine;
    machine << (status.driveOn ? CliText::tr("drive on") : CliText::tr("drive off"));
    if (status.spindleOn)
        machine << CliText::tr("spindle on");
    if (status.busy)
        machine << CliText::tr("busy");
    if (status.setupIncomplete)
        machine << CliText::tr("SETUP INCOMPLETE (write start-speed, max-speed and acceleration)");
    if (status.overTemperature)
        machine << CliText::tr("OVER TEMPERATURE");
    if (status.panic)
        machine << CliText::tr("EMERGENCY STOP ACTIVE");
    if (status.commFault)
        machine << CliText::tr("COMMUNICATION FAULT");
    if (status.motionUnconfirmed)
        machine << CliText::tr("MOTION UNCONFIRMED (an axis may still be moving)");

    QStringList lines;
    lines << CliText::tr("Model:        %1 (%2)").arg(model.id, model.displayName);
    lines << CliText::tr("Port:         %1 (%2)").arg(port, linkState);
    lines << CliText::tr("Machine:      %1").arg(machine.join(QStringLiteral(", ")));
    if (capabilities.temperature || status.temperatureCelsius) {
        lines << CliText::tr("Temperature:  %1")
                     .arg(status.temperatureCelsius
                              ? CliText::tr("%1 °C").arg(*status.temperatureCelsius, 0, 'f', 1)
                              : CliText::tr("not reported"));
    }
    if (!status.deviceFirmware.isEmpty())
        lines << CliText::tr("Firmware:     %1").arg(status.deviceFirmware);
    if (status.startButton)
        lines << CliText::tr("Start button: %1")
                     .arg(*status.startButton ? CliText::tr("pressed") : CliText::tr("released"));
    if (status.inputs) {
        QString levels;
        for (bool level : *status.inputs)
            levels += level ? QLatin1Char('1') : QLatin1Char('0');
        lines << CliText::tr("Inputs:       %1 (input 1 first)").arg(levels);
    }
    if (!status.outputs.isEmpty()) {
        QStringList states;
        for (int i = 0; i < status.outputs.size(); ++i) {
            const auto& o = status.outputs[i];
            states << QStringLiteral("%1:%2").arg(i + 1).arg(
                !o ? QStringLiteral("?") : (*o ? CliText::tr("on") : CliText::tr("off")));
        }
        lines << CliText::tr("Outputs:      %1 (? = not switched in this session)")
                     .arg(states.join(QLatin1Char(' ')));
    }
    if (status.doorOpen)
        lines << CliText::tr("Door:         %1")
                     .arg(*status.doorOpen ? CliText::tr("OPEN") : CliText::tr("closed"));
    if (capabilities.multiDrive && !status.drives.isEmpty())
        lines << driveLines(status.drives, names);
    int width = 4; // "Axis"
    for (auto it = status.axes.cbegin(); it != status.axes.cend(); ++it)
        width = qMax(width, int(names.name(it.key()).size()));
    lines << QStringLiteral("%1  %2")
                 .arg(CliText::tr("Axis"), -width)
                 .arg(CliText::tr("Moving  Jogging  Limit  Reference  Referenced  Position"));
    for (auto it = status.axes.cbegin(); it != status.axes.cend(); ++it) {
        const AxisStatus& a = it.value();
        lines << QStringLiteral("%1  %2  %3  %4  %5  %6  %7")
                     .arg(names.name(it.key()), -width)
                     .arg(yesNo(a.moving), -6)
                     .arg(yesNo(a.jogging), -7)
                     .arg(yesNo(a.limitSwitch), -5)
                     .arg(yesNo(a.referenceSwitch), -9)
                     .arg(yesNo(a.referenced), -10)
                     .arg(positionText(a));
    }
    QStringList raw;
    // Every drive's word decoded, not only the first four (issue 32).
    const QList<StatusWordInfo> words = model.presentation.statusWords
                                            ? model.presentation.statusWords(status.axes.keys())
                                            : QList<StatusWordInfo>();
    for (auto it = status.raw.cbegin(); it != status.raw.cend(); ++it)
        raw << QStringLiteral("%1=%2").arg(it.key(), rawValueText(it.key(), it.value(), words));
    if (!raw.isEmpty())
        lines << CliText::tr("Raw:          %1").arg(raw.join(QStringLiteral(" ")));
    return lines.join(QLatin1Char('\n'));
}

QString formatPositions(const MachineStatus& status)
{
    QStringList parts;
    for (auto it = status.axes.cbegin(); it != status.axes.cend(); ++it)
        parts << QStringLiteral("%1=%2").arg(axisName(it.key()), positionText(it.value()));
    return parts.join(QStringLiteral(" "));
}

} // namespace stepdeck::cli
