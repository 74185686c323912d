#pragma once
#include "NanotecBus.h"
#include "NanotecHostDrive.h"
#include "NanotecSteps.h"
#include "model/Axis.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

class NanotecController;
class NanotecExchange;

// Jog in the drive's speed mode (6.6, !2 p1): the drive ramps speed and direction changes by
// itself; a zero that persists lowers the speed to the start frequency and stops with 'S'.
class NanotecJog
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::NanotecController)

public:
    explicit NanotecJog(NanotecController& controller);

    static constexpr int kMaxRampWaitMs = 3000; // a longer ramp-down is cut short by 'S'

    void applyJogVelocity(const AxisVelocities& stepsPerS);
    double jogStopDistance(Axis axis, double speed) const;
    // Time the drive needs to ramp from fromHz down to its start frequency (6.11).
    int rampTimeMs(const HostDrive& d, double fromHz) const;

private:
    void pumpJog(Axis axis, bool zeroConfirmed = false);
    void startJog(HostDrive& d, double want, qint64 hz, double signedHz);
    void stopJog(HostDrive& d, bool zeroConfirmed);
    Done jogDone(Axis axis, JogPhase next, double applied);
    QList<Step> rampDownSteps(HostDrive& d, NanotecBus::Priority priority);

    NanotecController& m_ctl;
    NanotecExchange& m_link;
};

} // namespace stepdeck::nanotec
