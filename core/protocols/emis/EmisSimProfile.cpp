// What stepdeck-sim and the fault soak need of the SMC-IC4 simulator beyond the protocol
// (ModelInfo::scenario, soak).
#include "EmisModel.h"
#include "EmisSimulator.h"

namespace stepdeck::emis {

namespace {
ParameterValue sameOnEveryAxis(qint64 value)
{
    ParameterValue v;
    for (Axis a : emisAxes())
        v.perAxis.insert(a, value);
    return v;
}
} // namespace

ScenarioSupport scenarioSupport()
{
    ScenarioSupport s;
    s.options = ScenarioOption::Positions;
    // --position is where the carriage stands, in steps from its reference switch (the
    // board's own counter starts at 0 there, as at power-on).
    s.apply = [](const SimulatorScenario& scenario, Simulator* simulator, QString*) {
        auto* sim = qobject_cast<EmisSimulator*>(simulator);
        if (!sim)
            return false;
        for (auto it = scenario.positions.cbegin(); it != scenario.positions.cend(); ++it)
            sim->setPhysicalPosition(it.key(), it.value());
        sim->powerCycle(); // the counters start at 0 where the carriages stand
        return true;
    };
    return s;
}

SoakProfile soakProfile()
{
    SoakProfile m;
    m.setup = {{QStringLiteral("start-speed"), sameOnEveryAxis(500)},
               {QStringLiteral("work-speed"), sameOnEveryAxis(4000)},
               {QStringLiteral("ramp"), ParameterValue{QVariant(qint64(50)), {}}}};
    m.prepare = [](Simulator* s) {
        if (auto* sim = qobject_cast<EmisSimulator*>(s)) {
            for (Axis a : emisAxes())
                sim->setSwitchPosition(a, std::nullopt); // no reference switch within reach
        }
    };
    return m;
}

} // namespace stepdeck::emis
