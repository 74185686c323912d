// What stepdeck-sim and the fault soak need of the Nanotec bus simulator beyond the protocol
// (ModelInfo::scenario, soak).
#include "NanotecModel.h"
#include "NanotecSimulator.h"
#include "model/ModelOperations.h"

namespace stepdeck::nanotec {

namespace {
constexpr qint64 kFar = 1'000'000'000; // switches out of reach of any soak run

ParameterValue perAxis(qint64 value)
{
    ParameterValue v;
    for (Axis a : defaultAxisAddresses().keys())
        v.perAxis.insert(a, value);
    return v;
}
} // namespace

ScenarioSupport scenarioSupport()
{
    // The drives power on as the manual describes; besides --drives, stepdeck-sim takes the
    // closed-loop options (manual 8.1): drives without encoder, the calibration run's length.
    ScenarioSupport s;
    s.options = ScenarioOption::NoEncoder | ScenarioOption::CalibrationMs;
    s.apply = [](const SimulatorScenario& scenario, Simulator* simulator, QString* error) {
        auto* sim = qobject_cast<NanotecSimulator*>(simulator);
        if (!sim)
            return false;
        if (scenario.calibrationMs)
            sim->setCalibrationMs(*scenario.calibrationMs);
        for (int address : scenario.drivesWithoutEncoder) {
            if (!sim->drive(address)) {
                *error = NanotecSimulator::tr("--no-encoder: no drive at address %1 (see --drives)")
                             .arg(address);
                return false;
            }
            sim->setEncoderConnected(address, false);
        }
        return true;
    };
    return s;
}

SoakProfile soakProfile()
{
    SoakProfile m;
    m.simulatorAddresses = defaultAxisAddresses().values(); // the CLI's default machine
    m.readable = {QStringLiteral("phase-current"), QStringLiteral("max-frequency")};
    m.recovery = {operation::kResetPositionError};
    m.setup = {{QStringLiteral("max-frequency"), perAxis(8000)},
               {QStringLiteral("ramp"), perAxis(20)}}; // ramp 20: ~660 Hz/ms (6.11)
    m.prepare = [](Simulator* s) {
        if (auto* sim = qobject_cast<NanotecSimulator*>(s)) {
            for (NanotecDrive* d : sim->drives())
                d->setSwitches(-kFar, kFar);
        }
    };
    return m;
}

} // namespace stepdeck::nanotec
