#pragma once
// GUI tests of an EMIS SMC-IC4 machine: the main window connected to the in-process
// simulator through the connection bar, as an operator would connect.
#include "UiTestSupport.h"
#include "protocols/emis/EmisSimulator.h"

namespace stepdeck::test {

class EmisUiFixture : public UiFixture
{
public:
    bool connectEmis()
    {
        window->connectionBar()->setSelectedModel(QStringLiteral("emis"));
        window->connectionBar()->setPortSpec(QStringLiteral("sim"));
        window->connectionBar()->connectNow();
        return waitConnected();
    }

    bool withEmis(std::function<void(emis::EmisSimulator*)> fn)
    {
        return withSimulatorAs<emis::EmisSimulator>(std::move(fn));
    }

    // What the simulated board received, without the status polls, read in its thread.
    QList<QByteArray> boardCommands()
    {
        QList<QByteArray> out;
        withEmis([&out](emis::EmisSimulator* sim) {
            for (const QByteArray& c : sim->receivedCommands()) {
                if (c != "@IG")
                    out << c;
            }
        });
        return out;
    }
};

} // namespace stepdeck::test
