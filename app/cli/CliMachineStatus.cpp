// `stepdeck-cli --machine FILE status [--json]` and the positions that move, jog and home end
// with: every machine axis in its unit, marked by how it is known (docs/cli.md, "Machines").
#include "CliMachineRun.h"
#include "CliText.h"
#include "protocols/Registry.h"

namespace stepdeck::cli {

using machine::MachineAxis;
using machine::MachineAxisStatus;
using machine::MachineState;
using machine::PositionKnowledge;

namespace {
QString knownKey(PositionKnowledge known)
{
    switch (known) {
    case PositionKnowledge::Referenced:
        return QStringLiteral("referenced");
    case PositionKnowledge::Estimated:
        return QStringLiteral("estimated");
    case PositionKnowledge::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QString stateKey(MachineState state)
{
    switch (state) {
    case MachineState::Idle:
        return QStringLiteral("idle");
    case MachineState::Moving:
        return QStringLiteral("moving");
    case MachineState::Fault:
        return QStringLiteral("fault");
    case MachineState::Disconnected:
        return QStringLiteral("disconnected");
    case MachineState::LinkLost:
        break;
    }
    return QStringLiteral("link-lost");
}

// mm and deg with 3 decimals, steps whole: the device's count converted back.
QString valueText(const MachineAxis& a, double value)
{
    return a.unit == machine::AxisUnit::Step ? QString::number(qint64(value))
                                             : QString::number(value, 'f', 3);
}

QString markText(PositionKnowledge known)
{
    switch (known) {
    case PositionKnowledge::Referenced:
        return QString();
    case PositionKnowledge::Estimated:
        return CliText::tr(" (estimated)");
    case PositionKnowledge::Unknown:
        break;
    }
    return CliText::tr(" (unknown)");
}

QJsonArray axesJson(CliMachineSession& m)
{
    QJsonArray axes;
    for (const MachineAxis& a : m.description().axes) {
        const MachineAxisStatus s = m.machine().axisStatus(a);
        axes.append(QJsonObject{{"name", a.name},
                                {"controller", a.controller},
                                {"axis", m.description().controllerAxisName(a)},
                                {"unit", machine::unitKey(a.unit)},
                                {"position", s.position},
                                {"steps", s.steps},
                                {"known", knownKey(s.known)},
                                {"moving", s.moving}});
    }
    return axes;
}

QJsonArray controllersJson(CliMachineSession& m)
{
    QJsonArray controllers;
    for (const machine::MachineController& c : m.description().controllers) {
        const ControllerSession* s = m.machine().session(c.id);
        controllers.append(QJsonObject{{"id", c.id},
                                       {"model", c.modelId},
                                       {"port", c.port},
                                       {"link", linkStateName(s->linkState())}});
    }
    return controllers;
}

// A machine of one controller (--model/--port, or a file with one): the controller's own
// status object as a single controller always printed it ("model", "machine" flags, "axes"
// keyed by name, inputs, drives), each axis extended by the machine's fields, and the
// controller's link.
QJsonObject oneControllerJson(CliMachineSession& m)
{
    const machine::MachineController& c = m.description().controllers.constFirst();
    QJsonObject status = m.machine().session(c.id)->status().toJson(c.modelId);
    const QJsonObject controllerAxes = status.value("axes").toObject();
    QJsonObject axes;
    for (const QJsonValue& value : axesJson(m)) {
        const QJsonObject machineAxis = value.toObject();
        QJsonObject axis = controllerAxes.value(machineAxis.value("axis").toString()).toObject();
        for (auto it = machineAxis.begin(); it != machineAxis.end(); ++it)
            axis.insert(it.key(), it.value());
        axes.insert(machineAxis.value("name").toString(), axis);
    }
    status.insert("axes", axes);
    status.insert("controllers", controllersJson(m));
    return status;
}

void printAxisTable(CliMachineSession& m)
{
    int width = 1; // a letter; a bus's drives past the ninth go by their names (issue 32)
    for (const MachineAxis& a : m.description().axes)
        width = qMax(width, int(a.name.size()));
    for (const MachineAxis& a : m.description().axes) {
        const MachineAxisStatus s = m.machine().axisStatus(a);
        printLine(CliText::tr("  %1  %2 %3  (%4 steps on %5.%6)%7%8")
                      .arg(a.name, -width)
                      .arg(valueText(a, s.position), 12)
                      .arg(machine::unitKey(a.unit), -5)
                      .arg(s.steps)
                      .arg(a.controller, m.description().controllerAxisName(a))
                      .arg(markText(s.known))
                      .arg(s.moving ? CliText::tr(" moving") : QString()));
    }
}

// The controller's own lines (flags, temperature, drive rows, raw words) under the axis table.
void printControllerDetail(CliMachineSession& m, const machine::MachineController& c)
{
    const ControllerSession* s = m.machine().session(c.id);
    printLine(formatStatus(s->status(), *findModel(c.modelId), s->capabilities(), c.port,
                           linkStateName(s->linkState()), c.axisNames));
}

QString positionsText(CliMachineSession& m)
{
    QStringList parts;
    for (const MachineAxis& a : m.description().axes) {
        const MachineAxisStatus s = m.machine().axisStatus(a);
        parts << QStringLiteral("%1=%2%3").arg(a.name, valueText(a, s.position), markText(s.known));
    }
    return parts.join(QLatin1Char(' '));
}
} // namespace

Outcome printMachinePositions(CliMachineSession& m, bool json)
{
    if (json && m.description().controllers.size() == 1)
        printJson(oneControllerJson(m));
    else if (json)
        printJson(QJsonObject{{"axes", axesJson(m)}});
    else
        printLine(positionsText(m));
    return Outcome::success();
}

QString machinePositionsLine(CliMachineSession& m)
{
    return positionsText(m);
}

Outcome machineStatus(CliMachineSession& m, const CliOptions& o)
{
    if (!o.args.isEmpty())
        return Outcome::usage(CliText::tr("status takes no arguments"));
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    // The read prints what it read (stdout); what a controller did meanwhile by itself, such
    // as stopping motion the host did not command (docs/architecture.md, safety contract),
    // goes to stderr. The read itself succeeded: exit 0.
    for (const QString& note : m.notes())
        printError(note);
    QString cause;
    const MachineState state = m.machine().state(&cause);
    const QJsonValue causeJson = cause.isEmpty() ? QJsonValue() : QJsonValue(cause);
    if (o.json && m.description().controllers.size() == 1) {
        QJsonObject status = oneControllerJson(m);
        status.insert("state", stateKey(state));
        status.insert("stateCause", causeJson);
        printJson(status);
        return Outcome::success();
    }
    if (o.json) {
        printJson(QJsonObject{{"machine", m.description().name},
                              {"state", stateKey(state)},
                              {"stateCause", causeJson},
                              {"controllers", controllersJson(m)},
                              {"axes", axesJson(m)}});
        return Outcome::success();
    }
    printLine(cause.isEmpty()
                  ? CliText::tr("machine \"%1\": %2").arg(m.description().name, stateKey(state))
                  : CliText::tr("machine \"%1\": %2 (controller \"%3\")")
                        .arg(m.description().name, stateKey(state), cause));
    for (const machine::MachineController& c : m.description().controllers)
        printLine(QStringLiteral("  %1 %2 %3 %4")
                      .arg(c.id, -12)
                      .arg(c.modelId, -10)
                      .arg(c.port, -16)
                      .arg(linkStateName(m.machine().session(c.id)->linkState())));
    printAxisTable(m);
    if (m.description().controllers.size() == 1)
        printControllerDetail(m, m.description().controllers.constFirst());
    return Outcome::success();
}

} // namespace stepdeck::cli
