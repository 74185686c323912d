// What stepdeck-sim and the fault soak need of the laser motor-axis simulator beyond the
// protocol (ModelInfo::scenario, soak).
#include "LaserAxisSimulator.h"
#include "LaserCodec.h"
#include "LaserModel.h"
#include <QElapsedTimer>
#include <QThread>

namespace stepdeck::laser {

namespace {
constexpr qint64 kFar = 1'000'000'000; // switches out of reach of any soak run
const QList<Axis> kProfileAxes{Axis::X, Axis::Y, Axis::Z};

bool applyScenario(const SimulatorScenario& scenario, Simulator* simulator, QString*)
{
    auto* sim = qobject_cast<LaserAxisSimulator*>(simulator);
    if (!sim)
        return false;
    if (scenario.speed)
        sim->setSpeed(*scenario.speed);
    for (auto it = scenario.positions.cbegin(); it != scenario.positions.cend(); ++it)
        sim->powerOn(it.key(), it.value());
    for (auto it = scenario.endSwitches.cbegin(); it != scenario.endSwitches.cend(); ++it)
        sim->config(it.key()).endSwitch = it.value();
    sim->faults().silent = scenario.silent;
    sim->setGarbageBeforeStatus(scenario.garbage);
    return true;
}

// Every axis homed and standing mid-range (the protocol's positions are 0..99999), so the
// random walk of the soak's moves stays inside; then 2000 units/s, no ramps.
void prepareSoak(Simulator* s)
{
    auto* sim = qobject_cast<LaserAxisSimulator*>(s);
    if (!sim)
        return;
    const bool silent = s->faults().silent;
    s->faults().silent = true; // the status frames of the set-up reach nobody
    sim->setSpeed(1e9);
    for (Axis a : kProfileAxes) {
        sim->config(a).endSwitch = kFar;
        sim->receive(encodeMove(a, kMaxPosition / 2));
    }
    QElapsedTimer clock;
    clock.start();
    while (!sim->standingStill() && clock.elapsed() < 2000)
        QThread::msleep(1);
    sim->clearAcceptedMoves();
    sim->setSpeed(2000);
    s->faults().silent = silent;
}
} // namespace

ScenarioSupport scenarioSupport()
{
    ScenarioSupport s;
    s.options = ScenarioOption::Positions | ScenarioOption::Speed | ScenarioOption::EndSwitches |
                ScenarioOption::Silent | ScenarioOption::Garbage;
    s.apply = &applyScenario;
    return s;
}

SoakProfile soakProfile()
{
    SoakProfile m;
    m.prepare = &prepareSoak;
    // The axes report their position only in a status frame after a command: the host first
    // sends each axis to where it stands (a zero-length move the device journal leaves out).
    m.anchorPositions = true;
    return m;
}

} // namespace stepdeck::laser
