#include "SwitchExecutor.h"
#include "machine/Machine.h"
#include "model/ModelOperations.h"
#include <algorithm>

namespace stepdeck::motion {

SwitchExecutor::SwitchExecutor(const machine::MachineDescription& description,
                               const QMap<QString, Capabilities>& capabilities,
                               const QMap<QString, ParameterSchema>& schemas)
    : m_d(description), m_caps(capabilities), m_schemas(schemas)
{}

QString SwitchExecutor::wordOf(const MotionCommand& command)
{
    if (const auto* on = std::get_if<SpindleOn>(&command))
        return on->reverse ? QStringLiteral("M4") : QStringLiteral("M3");
    if (std::holds_alternative<SpindleSpeed>(command))
        return QStringLiteral("S");
    if (std::holds_alternative<SpindleOff>(command))
        return QStringLiteral("M5");
    if (const auto* coolant = std::get_if<Coolant>(&command))
        return coolant->kind == Coolant::Kind::Mist    ? QStringLiteral("M7")
               : coolant->kind == Coolant::Kind::Flood ? QStringLiteral("M8")
                                                       : QStringLiteral("M9");
    if (const auto* output = std::get_if<Output>(&command))
        return QStringLiteral("%1 P%2")
            .arg(output->on ? QStringLiteral("M64") : QStringLiteral("M65"))
            .arg(output->number);
    return {};
}

std::optional<SwitchExecutor::Refusal> SwitchExecutor::accepts(const MotionCommand& command) const
{
    if (std::holds_alternative<SpindleOn>(command) ||
        std::holds_alternative<SpindleSpeed>(command) ||
        std::holds_alternative<SpindleOff>(command))
        return acceptsSpindle(command);
    if (std::holds_alternative<Coolant>(command)) {
        if (!switchController(&Capabilities::coolant).isEmpty())
            return std::nullopt;
        return Refusal{ErrorKind::Unsupported,
                       {},
                       tr("%1: no controller of this machine has coolant").arg(wordOf(command))};
    }
    if (const auto* out = std::get_if<Output>(&command))
        return acceptsOutput(*out);
    return std::nullopt;
}

// M3/M4 S, an S of its own and M5: a controller with a spindle; M4 where it reverses (or a
// laser's); S within the machine's spindle scale and the range its controller takes.
std::optional<SwitchExecutor::Refusal>
SwitchExecutor::acceptsSpindle(const MotionCommand& command) const
{
    const QString word = wordOf(command);
    const QString controller = switchController(&Capabilities::spindle);
    if (controller.isEmpty())
        return Refusal{ErrorKind::Unsupported,
                       {},
                       tr("%1: no controller of this machine has a spindle").arg(word)};
    const Capabilities caps = m_caps.value(controller);
    const auto* on = std::get_if<SpindleOn>(&command);
    if (on && on->reverse) {
        if (const QString why = spindleReverse(caps, controller, m_d.spindle); !why.isEmpty())
            return Refusal{ErrorKind::Unsupported, {}, QStringLiteral("%1: %2").arg(word, why)};
    }
    const auto* speed = std::get_if<SpindleSpeed>(&command);
    if (!on && !speed)
        return std::nullopt; // M5
    const double rpm = on ? on->rpm : speed->rpm;
    const QString why =
        spindleSpeed(caps, m_schemas.value(controller), m_d.spindle.maxRpm, rpm, m_d.limits);
    if (why.isEmpty())
        return std::nullopt;
    return Refusal{ErrorKind::InvalidValue, QStringLiteral("S"),
                   tr("controller \"%1\": %2").arg(controller, why)};
}

std::optional<SwitchExecutor::Refusal> SwitchExecutor::acceptsOutput(const Output& out) const
{
    if (output(out.number))
        return std::nullopt;
    int count = 0;
    for (const machine::MachineController& c : m_d.controllers)
        count += m_caps.value(c.id).digitalOutputs;
    const QString word = wordOf(out);
    return Refusal{ErrorKind::Unsupported, QStringLiteral("P"),
                   count == 0 ? tr("%1: the machine has no digital outputs").arg(word)
                              : tr("%1: the machine's outputs are 1..%2").arg(word).arg(count)};
}

double SwitchExecutor::estimate(const MotionCommand&) const
{
    return 0;
}

RequestId SwitchExecutor::push(const MotionCommand& command, machine::Machine& machine,
                               QString* controller) const
{
    if (accepts(command))
        return 0;
    QString id;
    if (std::holds_alternative<SpindleOn>(command) ||
        std::holds_alternative<SpindleSpeed>(command) ||
        std::holds_alternative<SpindleOff>(command))
        id = switchController(&Capabilities::spindle);
    else if (std::holds_alternative<Coolant>(command))
        id = switchController(&Capabilities::coolant);
    else if (const auto* out = std::get_if<Output>(&command))
        id = output(out->number).value_or(Io{}).controller;
    ControllerSession* s = id.isEmpty() ? nullptr : machine.session(id);
    if (!s)
        return 0;
    if (controller)
        *controller = id;
    if (const auto* on = std::get_if<SpindleOn>(&command))
        return s->setSpindle(
            spindleValue(s->capabilities(), s->schema(), m_d.spindle.maxRpm, on->rpm));
    if (const auto* speed = std::get_if<SpindleSpeed>(&command))
        return s->setSpindle(
            spindleValue(s->capabilities(), s->schema(), m_d.spindle.maxRpm, speed->rpm));
    if (std::holds_alternative<SpindleOff>(command))
        return s->setSpindle(0);
    if (const auto* coolant = std::get_if<Coolant>(&command))
        return s->setCoolant(coolant->kind != Coolant::Kind::Off);
    const auto& out = std::get<Output>(command);
    return s->modelOperation(
        operation::kSetOutput,
        {{operation::arg::kOutput, output(out.number)->number}, {operation::arg::kOn, out.on}});
}

QString SwitchExecutor::switchController(bool Capabilities::*has) const
{
    for (const machine::MachineController& c : m_d.controllers)
        if (m_caps.value(c.id).*has)
            return c.id;
    return {};
}

std::optional<SwitchExecutor::Io> SwitchExecutor::nthIo(int n, int Capabilities::*count) const
{
    if (n < 1)
        return std::nullopt;
    for (const machine::MachineController& c : m_d.controllers) {
        const int here = m_caps.value(c.id).*count;
        if (n <= here)
            return Io{c.id, n};
        n -= here;
    }
    return std::nullopt;
}

std::optional<SwitchExecutor::Io> SwitchExecutor::output(int n) const
{
    return nthIo(n, &Capabilities::digitalOutputs);
}

std::optional<SwitchExecutor::Io> SwitchExecutor::input(int n) const
{
    return nthIo(n, &Capabilities::digitalInputs);
}

double SwitchExecutor::spindleRpm(double s, std::optional<double> maxRpm)
{
    return maxRpm && *maxRpm > 0 && s > *maxRpm ? *maxRpm : s;
}

namespace {
const ParameterSpec* spindleSpec(const Capabilities& caps, const ParameterSchema& schema)
{
    return caps.spindleSpeedParameter ? schema.find(QString::fromLatin1(caps.spindleSpeedParameter))
                                      : nullptr;
}
} // namespace

int SwitchExecutor::spindleValue(const Capabilities& caps, const ParameterSchema& schema,
                                 std::optional<double> maxRpm, double s)
{
    const ParameterSpec* spec = spindleSpec(caps, schema);
    // The program's S is 0..1 000 000 (ProgramLineChecks), so every value here fits an int.
    if (!maxRpm || *maxRpm <= 0 || !spec || spec->maximum <= 0 || s <= 0)
        return qRound(s);
    const double scaled = spindleRpm(s, maxRpm) / *maxRpm * double(spec->maximum);
    return std::max(1, qRound(scaled));
}

QString SwitchExecutor::spindleSpeed(const Capabilities& caps, const ParameterSchema& schema,
                                     std::optional<double> maxRpm, double s,
                                     machine::LimitPolicy limits)
{
    if (maxRpm && s > *maxRpm && limits == machine::LimitPolicy::Refuse)
        return tr("S%1 is above the spindle's maxRpm %2 (the machine file's spindle scale)")
            .arg(s)
            .arg(*maxRpm);
    const ParameterSpec* spec = spindleSpec(caps, schema);
    if (!spec)
        return {};
    return schema.validateScalar(*spec, spindleValue(caps, schema, maxRpm, s));
}

QString SwitchExecutor::spindleReverse(const Capabilities& caps, const QString& controller,
                                       const machine::MachineSpindle& spindle)
{
    if (caps.spindleReverse || spindle.laser)
        return {};
    return tr("controller \"%1\" cannot reverse its spindle: use M3").arg(controller);
}

} // namespace stepdeck::motion
