// What stepdeck-sim, the fault soak and the benchmarks need of the E-LAB simulator beyond the
// protocol (ModelInfo::scenario, soak, streamBench): the machine options it takes, how the
// soak drives it, and how the DC2 stream is counted on the wire.
#include "ElabCodec.h"
#include "ElabModel.h"
#include "ElabSimulator.h"
#include "sim/TrafficMeter.h"

namespace stepdeck::elab {

namespace {
constexpr qint64 kFar = 1'000'000'000; // switches out of reach of any soak run
const QList<Axis> kAxes{Axis::X, Axis::Y, Axis::Z};

bool applyScenario(const SimulatorScenario& scenario, Simulator* simulator, QString*)
{
    auto* sim = qobject_cast<ElabSimulator*>(simulator);
    if (!sim)
        return false;
    if (scenario.setupComplete) {
        // Through the protocol itself, exactly as a host would do it (manual: Setup Befehle);
        // the simulator is not attached yet, so its ACKs go nowhere.
        const Triple<quint16> start{100, 100, 100};
        const Triple<quint16> max{5000, 5000, 5000};
        const Triple<quint16> accel{1000, 1000, 1000};
        const bool paced = sim->options().paceOutput;
        sim->setPacing(false, sim->options().line);
        sim->receive(encode::ramp(RampKind::StartSpeed, start) +
                     encode::ramp(RampKind::MaxSpeed, max) +
                     encode::ramp(RampKind::Acceleration, accel));
        sim->setPacing(paced, sim->options().line);
    }
    if (scenario.temperature)
        sim->setTemperature(*scenario.temperature);
    for (auto it = scenario.limits.cbegin(); it != scenario.limits.cend(); ++it)
        sim->setLimitPositions(it.key(), it.value().minimum, it.value().maximum);
    for (auto it = scenario.positions.cbegin(); it != scenario.positions.cend(); ++it)
        sim->setPosition(it.key(), it.value());
    // The reference switch at the simulated machine's distance (ElabSimSwitchConfig), on the
    // side the machine's reference run searches.
    const ElabSimSwitchConfig defaults;
    for (auto it = scenario.referenceSides.cbegin(); it != scenario.referenceSides.cend(); ++it)
        sim->setReferencePosition(it.key(), it.value() * qAbs(defaults.referencePosition),
                                  defaults.referenceWindow);
    return true;
}

// The host's bytes as the board receives them (manual, SetFeedStepXYZ): <DC2> is followed by
// one raw step byte, which may take any value with bits 7 and 3 clear -- including 0x07
// (<BEL>, ForcePanicStop) or 0x13 (<XOFF>, Force Stop Move), so the pairs are tracked.
class StreamMeter : public TrafficMeter
{
public:
    void scan(const QByteArray& bytes, qint64 nowNs) override
    {
        for (const char byte : bytes) {
            if (m_afterDc2) {
                m_afterDc2 = false;
                noteStep(nowNs);
            } else if (byte == ctrl::DC2) {
                m_afterDc2 = true;
            } else if (byte == ctrl::BEL) {
                notePanic(nowNs);
            } else if (byte == ctrl::XOFF) {
                noteStop(nowNs);
            }
        }
    }

private:
    bool m_afterDc2 = false;
};

ParameterValue perAxis(qint64 value)
{
    ParameterValue v;
    for (Axis a : kAxes)
        v.perAxis.insert(a, value);
    return v;
}
} // namespace

ScenarioSupport scenarioSupport()
{
    ScenarioSupport s;
    s.options = ScenarioOption::SetupComplete | ScenarioOption::Temperature |
                ScenarioOption::Limits | ScenarioOption::Positions | ScenarioOption::ReferenceSides;
    s.apply = &applyScenario;
    return s;
}

SoakProfile soakProfile()
{
    SoakProfile m;
    m.setup = {{QStringLiteral("start-speed"), perAxis(500)},
               {QStringLiteral("max-speed"), perAxis(8000)},
               {QStringLiteral("acceleration"), perAxis(20000)},
               {QStringLiteral("feed-speed"), perAxis(200)}};
    m.prepare = [](Simulator* s) {
        if (auto* sim = qobject_cast<ElabSimulator*>(s)) {
            for (Axis a : kAxes)
                sim->setLimitPositions(a, -kFar, kFar);
        }
    };
    return m;
}

StreamBenchProfile streamBenchProfile()
{
    StreamBenchProfile b;
    b.createMeter = [] { return std::unique_ptr<TrafficMeter>(new StreamMeter); };
    b.unlimitBuffer = [](Simulator* s) {
        if (auto* sim = qobject_cast<ElabSimulator*>(s))
            sim->setStreamBuffer(1 << 24, (1 << 24) - 64, 1 << 23);
    };
    b.hostPaused = [](Simulator* s) {
        auto* sim = qobject_cast<ElabSimulator*>(s);
        return sim && sim->streamHostPaused();
    };
    return b;
}

} // namespace stepdeck::elab
