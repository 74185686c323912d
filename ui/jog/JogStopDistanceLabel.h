#pragma once
#include "common/ElidedLabel.h"
#include "jog/JogSlot.h"
#include <optional>

namespace stepdeck::ui {

class JogController;
class MachineContext;

// How far each jog slot's axis travels after a release from the current jog speed setting
// (its max speed x the override): "Stops within X 0.80 mm, Y 0.80 mm" (issue 28 item 6).
// The distance is the controller's host ramp's (JogRamp::stopDistance with the ramp the
// machine's jogAcceleration set, ControllerOptions::jogAccelerationStepsPerS2); axes whose
// drive brakes by its own ramp (Capabilities::hostRampedJog false) are not given a figure.
// An ElidedLabel of two reserved lines: its size never depends on the text, so a changed
// speed never re-flows the panel under the operator's hand (docs/architecture.md).
class JogStopDistanceLabel : public ElidedLabel
{
    Q_OBJECT
public:
    JogStopDistanceLabel(MachineContext* context, JogController* jog, QWidget* parent = nullptr);

    // The slot's stopping distance in its unit (steps without a machine) at `speed` (the
    // slot's rate unit); none where the host ramp does not brake it.
    std::optional<double> stopDistance(JogSlot slot, double speed) const;

public Q_SLOTS:
    void refresh();

private:
    QString slotText(JogSlot slot) const;

    MachineContext* m_context;
    JogController* m_jog;
};

} // namespace stepdeck::ui
