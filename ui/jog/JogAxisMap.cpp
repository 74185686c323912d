#include "JogAxisMap.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QSettings>

namespace stepdeck::ui {

namespace {

// The pad takes X and Y when the machine has both, else its first two axes (file order).
QStringList padAxes(const machine::MachineDescription& d)
{
    if (d.axis(QStringLiteral("X")) && d.axis(QStringLiteral("Y")))
        return {QStringLiteral("X"), QStringLiteral("Y")};
    QStringList out;
    for (const machine::MachineAxis& a : d.axes) {
        if (out.size() < 2 && a.name != QLatin1String("Z"))
            out << a.name;
    }
    return out;
}

} // namespace

JogAxisMap::JogAxisMap(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context)
{
    // A new machine announces its model first (MachineContext::install): the slots follow at
    // once, before the panels that rebuild on the model ask them.
    connect(context, &MachineContext::modelChanged, this, &JogAxisMap::rebuild);
    connect(context, &MachineContext::machineChanged, this, &JogAxisMap::rebuild);
    rebuild();
}

bool JogAxisMap::isMachine() const
{
    return m_context->hasMachine();
}

bool JogAxisMap::jogsByTargets() const
{
    const machine::Machine* machine = m_context->machine();
    if (!machine)
        return false;
    for (const machine::MachineController& c : machine->description().controllers) {
        if (machine->session(c.id)->capabilities().jogByTargets)
            return true;
    }
    return false;
}

void JogAxisMap::rebuild()
{
    m_slots.clear();
    m_maxSpeed.clear();
    if (isMachine()) {
        const machine::MachineDescription& d = m_context->machine()->description();
        const QStringList pad = padAxes(d);
        if (!pad.isEmpty())
            m_slots.insert(JogSlot::PadHorizontal, pad.first());
        if (pad.size() > 1)
            m_slots.insert(JogSlot::PadVertical, pad.at(1));
        if (d.axis(QStringLiteral("Z")))
            m_slots.insert(JogSlot::ZStick, QStringLiteral("Z"));
        const QStringList others = otherStickChoices();
        if (!others.isEmpty())
            m_slots.insert(JogSlot::OtherStick, others.first());
        const QSettings settings;
        for (const machine::MachineAxis& a : d.axes) {
            const double fallback =
                a.maxJogSpeed ? *a.maxJogSpeed : qMin(ceilingOf(a), 1000.0 / a.stepsPerUnit);
            const double stored = settings.value(settingsKey(a.name), fallback).toDouble();
            m_maxSpeed.insert(a.name, qBound(0.0, stored, ceilingOf(a)));
        }
    }
    Q_EMIT changed();
}

QList<JogSlot> JogAxisMap::jogSlots() const
{
    return m_slots.keys();
}

const machine::MachineAxis* JogAxisMap::machineAxis(JogSlot slot) const
{
    if (!isMachine() || !m_slots.contains(slot))
        return nullptr;
    return m_context->machine()->description().axis(m_slots.value(slot));
}

QString JogAxisMap::label(JogSlot slot) const
{
    return m_slots.value(slot);
}

QStringList JogAxisMap::otherStickChoices() const
{
    QStringList out;
    if (!isMachine())
        return out;
    for (const machine::MachineAxis& a : m_context->machine()->description().axes) {
        const bool taken = (m_slots.value(JogSlot::PadHorizontal) == a.name ||
                            m_slots.value(JogSlot::PadVertical) == a.name ||
                            m_slots.value(JogSlot::ZStick) == a.name);
        if (!taken)
            out << a.name;
    }
    return out;
}

void JogAxisMap::setOtherStickAxis(const QString& name)
{
    if (!otherStickChoices().contains(name) || m_slots.value(JogSlot::OtherStick) == name)
        return;
    // Whatever the stick held moved the old axis: the caller releases it first (changed()).
    m_slots.insert(JogSlot::OtherStick, name);
    Q_EMIT changed();
}

double JogAxisMap::ceilingOf(const machine::MachineAxis& axis) const
{
    if (axis.maxJogSpeed)
        return *axis.maxJogSpeed;
    const ControllerSession* s = m_context->machine()->session(axis.controller);
    return s->capabilities().maxJogSpeed / axis.stepsPerUnit;
}

double JogAxisMap::ceiling(JogSlot slot) const
{
    const machine::MachineAxis* a = machineAxis(slot);
    return a ? ceilingOf(*a) : 0.0;
}

double JogAxisMap::maxSpeed(JogSlot slot) const
{
    const machine::MachineAxis* a = machineAxis(slot);
    return a ? m_maxSpeed.value(a->name) : 0.0;
}

void JogAxisMap::setMaxSpeed(JogSlot slot, double unitsPerSecond)
{
    const machine::MachineAxis* a = machineAxis(slot);
    if (!a)
        return;
    const double value = qBound(0.0, unitsPerSecond, ceilingOf(*a));
    m_maxSpeed.insert(a->name, value);
    QSettings().setValue(settingsKey(a->name), value);
}

QString JogAxisMap::settingsKey(const QString& axisName) const
{
    return QStringLiteral("jog/machine/%1/%2/maxSpeed")
        .arg(m_context->machine()->description().name, axisName);
}

QMap<QString, double> JogAxisMap::machineRates(const SlotVelocities& slotRates) const
{
    QMap<QString, double> out;
    for (auto it = slotRates.cbegin(); it != slotRates.cend(); ++it) {
        if (m_slots.contains(it.key()))
            out.insert(m_slots.value(it.key()), it.value());
    }
    return out;
}

AxisStatus JogAxisMap::slotStatus(JogSlot slot, double* velocity) const
{
    AxisStatus status;
    if (const machine::MachineAxis* a = machineAxis(slot)) {
        *velocity = commandedUnitsPerSecond(m_context, *a, &status);
    } else {
        *velocity = 0.0;
    }
    return status;
}

QString rateUnitName(const machine::MachineAxis& axis)
{
    switch (axis.unit) {
    case machine::AxisUnit::Millimetre:
        return JogAxisMap::tr("mm/s");
    case machine::AxisUnit::Degree:
        return JogAxisMap::tr("deg/s");
    case machine::AxisUnit::Step:
        break;
    }
    return JogAxisMap::tr("steps/s");
}

double commandedUnitsPerSecond(MachineContext* context, const machine::MachineAxis& axis,
                               AxisStatus* status)
{
    const ControllerSession* s = context->machine()->session(axis.controller);
    const AxisStatus st = s->status().axes.value(axis.axis);
    if (status)
        *status = st;
    const double rate = st.commandedVelocity / axis.stepsPerUnit;
    return axis.invert ? -rate : rate;
}

} // namespace stepdeck::ui
