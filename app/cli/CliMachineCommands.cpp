// `machine check FILE`: validates a machine description (docs/machines.md) and prints the
// resolved controllers and axes, or the first error naming its field (exit 7).
#include "CliCommands.h"
#include "CliMachineRun.h"
#include "CliText.h"
#include "machine/MachineFile.h"
#include <QFileInfo>
#include <QJsonArray>

namespace stepdeck::cli {

namespace {
using machine::MachineAxis;
using machine::MachineController;
using machine::MachineDescription;

// Axes go by the names the file gives them (issue 47, 11b: "feed1=1", "bus.feed1"), and by their
// default names (X, Y, Z, U, axis5, ...) where it gives none.
QString controllerLine(const MachineController& c)
{
    QStringList extra;
    if (!c.busAddresses.isEmpty()) {
        QStringList map;
        for (auto it = c.busAddresses.cbegin(); it != c.busAddresses.cend(); ++it)
            map << QStringLiteral("%1=%2").arg(c.axisNames.name(it.key())).arg(it.value());
        extra << CliText::tr("drives %1").arg(map.join(QLatin1Char(',')));
    }
    if (c.resetLine)
        extra << CliText::tr("reset line %1").arg(resetLineName(*c.resetLine));
    return QStringLiteral("  %1 %2 %3 %4")
        .arg(c.id, -12)
        .arg(c.modelId, -10)
        .arg(c.port, -16)
        .arg(extra.join(QStringLiteral("; ")))
        .trimmed();
}

QString axisLine(const MachineDescription& m, const MachineAxis& a)
{
    const QString limits = a.hasSoftLimits()
                               ? QStringLiteral("%1..%2").arg(*a.softMinimum).arg(*a.softMaximum)
                               : CliText::tr("no limits");
    return QStringLiteral("  %1  %2 %3 %4 %5 %6 %7")
        .arg(a.name)
        .arg(a.controller + QLatin1Char('.') + m.controllerAxisName(a), -14)
        .arg(machine::unitKey(a.unit), -5)
        .arg(CliText::tr("%1 steps/%2").arg(a.stepsPerUnit).arg(machine::unitKey(a.unit)), -20)
        .arg(a.invert ? CliText::tr("inverted") : QString(), -8)
        .arg(limits, -16)
        .arg(CliText::tr("reference order %1").arg(a.referenceOrder));
}

} // namespace

void printMachineTable(const MachineDescription& m)
{
    printLine(CliText::tr("machine \"%1\": %2 controllers, %3 axes")
                  .arg(m.name)
                  .arg(m.controllers.size())
                  .arg(m.axes.size()));
    for (const MachineController& c : m.controllers)
        printLine(controllerLine(c));
    for (const QList<const MachineAxis*>& group : m.referenceGroups()) {
        for (const MachineAxis* a : group)
            printLine(axisLine(m, *a));
    }
}

Outcome cmdMachine(CliContext& c, QStringList args)
{
    if (args.size() != 2 || args.at(0) != QLatin1String("check"))
        return Outcome::usage(CliText::tr("usage: machine check FILE"));
    const QString path = args.at(1);
    if (!QFileInfo(path).isReadable())
        return Outcome::failure(ExitFile, CliText::tr("cannot read %1").arg(path));
    machine::MachineFileError error;
    const std::optional<MachineDescription> m = machine::MachineFile::load(path, &error);
    if (!m)
        return Outcome::failure(
            ExitInvalidValue, CliText::tr("%1: %2").arg(QFileInfo(path).fileName(), error.text()));
    if (c.json())
        printJson(m->toJson());
    else
        printMachineTable(*m);
    return Outcome::success();
}

} // namespace stepdeck::cli
