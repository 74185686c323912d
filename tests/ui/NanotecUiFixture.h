#pragma once
// GUI tests of a Nanotec machine: the main window connected to the in-process bus simulator
// with the axis map X=1, Y=2, Z=3.
#include "UiTestSupport.h"
#include "protocols/nanotec/NanotecSimulator.h"

namespace stepdeck::test {

class NanotecUiFixture : public UiFixture
{
public:
    // busText: the drives as --axes lists them; default X=1,Y=2,Z=3. timeoutMs: how long to
    // wait for the connection (a full bus under the sanitizers on a loaded machine needs more).
    bool connectNanotec(const QString& busText = QStringLiteral("X=1,Y=2,Z=3"),
                        int timeoutMs = 15000)
    {
        ConnectionSpec spec{QStringLiteral("sim"), {}, {}};
        QList<NamedAddress> bus;
        QString error;
        if (!parseNamedAddresses(busText, &bus, &error) ||
            !assignBusAxes(bus, &spec.options.axisAddresses, &spec.options.axisNames, &error)) {
            qWarning() << error;
            return false;
        }
        spec.simulator.addresses = spec.options.axisAddresses.values();
        if (!window->context()->connectTo(*findModel(QStringLiteral("nanotec")), spec, &error)) {
            qWarning() << error;
            return false;
        }
        return waitConnected(timeoutMs);
    }

    // Six drives named as a plant calls them (issue 32), at addresses 1..6.
    static QString sixNamedDrives()
    {
        return QStringLiteral("feeder=1,gate=2,press=3,lift=4,tilt=5,stacker=6");
    }

    bool withBus(std::function<void(nanotec::NanotecSimulator*)> fn)
    {
        return withSimulatorAs<nanotec::NanotecSimulator>(std::move(fn));
    }
};

} // namespace stepdeck::test
