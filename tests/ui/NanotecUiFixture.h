#pragma once
// GUI tests of a Nanotec machine: the main window connected to the in-process bus simulator
// with the axis map X=1, Y=2, Z=3.
#include "UiTestSupport.h"
#include "protocols/nanotec/NanotecSimulator.h"

namespace stepdeck::test {

class NanotecUiFixture : public UiFixture
{
public:
    bool connectNanotec()
    {
        ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
        spec.options.axisAddresses = {{Axis::X, 1}, {Axis::Y, 2}, {Axis::Z, 3}};
        spec.simulator.addresses = {1, 2, 3};
        QString error;
        if (!window->context()->connectTo(*findModel(QStringLiteral("nanotec")), spec, &error)) {
            qWarning() << error;
            return false;
        }
        return waitConnected();
    }

    bool withBus(std::function<void(nanotec::NanotecSimulator*)> fn)
    {
        return withSimulatorAs<nanotec::NanotecSimulator>(std::move(fn));
    }
};

} // namespace stepdeck::test
