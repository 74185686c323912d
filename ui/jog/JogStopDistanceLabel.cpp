#include "JogStopDistanceLabel.h"
#include "controller/JogRamp.h"
#include "jog/JogAxisMap.h"
#include "jog/JogController.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QtMath>

namespace stepdeck::ui {

namespace {
// The ramp the controller brakes a jog with, steps/s^2, and its tick (Controller::onJogTick).
double rampOf(const ControllerSession* session, const Capabilities& caps)
{
    const double set = session->spec().options.jogAccelerationStepsPerS2;
    return set > 0 ? set : caps.defaultJogAcceleration;
}
double tickOf(const ControllerSession* session)
{
    return qMax(5, session->spec().options.jogTickMs) / 1000.0;
}
} // namespace

JogStopDistanceLabel::JogStopDistanceLabel(MachineContext* context, JogController* jog,
                                           QWidget* parent)
    : ElidedLabel(parent, 3), m_context(context), m_jog(jog)
{
    setObjectName(QStringLiteral("jogStopDistance"));
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    setToolTip(tr("How far each axis still travels after the pad, key or gamepad is let go at "
                  "the jog speed set now (max speed x override)"));
    connect(jog, &JogController::speedSettingsChanged, this, &JogStopDistanceLabel::refresh);
    connect(jog->axisMap(), &JogAxisMap::changed, this, &JogStopDistanceLabel::refresh);
    connect(context, &MachineContext::modelChanged, this, &JogStopDistanceLabel::refresh);
    connect(context, &MachineContext::machineChanged, this, &JogStopDistanceLabel::refresh);
    refresh();
}

std::optional<double> JogStopDistanceLabel::stopDistance(JogSlot slot, double speed) const
{
    const JogAxisMap* map = m_jog->axisMap();
    const machine::MachineAxis* axis = map->machineAxis(slot);
    if (!axis)
        return std::nullopt;
    const ControllerSession* s = m_context->machine()->session(axis->controller);
    const Capabilities caps = s ? s->capabilities() : Capabilities{};
    if (!s || !caps.hostRampedJog)
        return std::nullopt;
    const double stepsPerS = speed * axis->stepsPerUnit;
    return JogRamp::stopDistance(stepsPerS, rampOf(s, caps), tickOf(s)) / axis->stepsPerUnit;
}

QString JogStopDistanceLabel::slotText(JogSlot slot) const
{
    const std::optional<double> d = stopDistance(slot, m_jog->maxSpeed(slot) * m_jog->override());
    if (!d)
        return {};
    const JogAxisMap* map = m_jog->axisMap();
    const machine::MachineAxis* axis = map->machineAxis(slot);
    const machine::AxisUnit unit = axis ? axis->unit : machine::AxisUnit::Step;
    switch (unit) {
    case machine::AxisUnit::Millimetre:
        return tr("%1 %2 mm").arg(map->label(slot)).arg(*d, 0, 'f', 2);
    case machine::AxisUnit::Degree:
        return tr("%1 %2 deg").arg(map->label(slot)).arg(*d, 0, 'f', 2);
    case machine::AxisUnit::Step:
        break;
    }
    return tr("%1 %2 steps").arg(map->label(slot)).arg(qCeil(*d));
}

void JogStopDistanceLabel::refresh()
{
    QStringList parts;
    for (JogSlot slot : m_jog->axisMap()->jogSlots()) {
        const QString part = slotText(slot);
        if (!part.isEmpty())
            parts << part;
    }
    setText(parts.isEmpty() ? tr("Stops by the controller's own ramp after a release")
                            : tr("Stops within %1").arg(parts.join(QStringLiteral(", "))));
}

} // namespace stepdeck::ui
