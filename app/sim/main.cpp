// stepdeck-sim: a simulated controller on a pseudo-terminal (issue #2, section 4).
// The first stdout line is the slave path; tests read it and point stepdeck-cli at it.
#include "../common/SignalPipe.h"
#include "SimMachine.h"
#include "SimScenario.h"
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QCoreApplication>
#include <cstdio>

using namespace stepdeck;

namespace {
void printTo(FILE* stream, const QString& text)
{
    const QByteArray bytes = text.toUtf8() + '\n';
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stream);
    std::fflush(stream);
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stepdeck-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPDECK_VERSION));

    simapp::SimScenario scenario;
    QString error;
    if (!simapp::parseScenario(application.arguments().mid(1), &scenario, &error)) {
        printTo(stderr, QStringLiteral("stepdeck-sim: %1").arg(error));
        return 2;
    }
    if (scenario.help) {
        printTo(stdout, simapp::simUsage());
        return 0;
    }
    if (scenario.version) {
        printTo(stdout,
                QStringLiteral("stepdeck-sim %1").arg(QCoreApplication::applicationVersion()));
        return 0;
    }
    if (!scenario.machineFile.isEmpty())
        return simapp::runMachine(scenario);
    const ModelInfo* model =
        scenario.model.isEmpty() ? &models().first() : findModel(scenario.model);
    if (!model || !model->createSimulator) {
        printTo(stderr, QStringLiteral("stepdeck-sim: %1")
                            .arg(simapp::SimText::tr("unknown controller model '%1' (known: %2)")
                                     .arg(scenario.model, modelIds().join(QStringLiteral(", ")))));
        return 2;
    }

    SimulatorOptions options;
    options.addresses = scenario.drives;
    options.paceOutput = scenario.pace;
    options.line = model->line;
    options.seed = scenario.seed;
    Simulator* simulator = model->createSimulator(options);
    simulator->setParent(&application);
    if (!simapp::applyScenario(scenario, *model, simulator, &error)) {
        printTo(stderr, QStringLiteral("stepdeck-sim: %1").arg(error));
        return 2;
    }
    simapp::applyFaults(scenario, simulator);

    PtyEndpoint endpoint;
    if (!endpoint.create(&error)) {
        printTo(stderr, QStringLiteral("stepdeck-sim: %1").arg(error));
        return 1;
    }
    QObject::connect(&endpoint, &Transport::failed, &application, [](const QString& reason) {
        printTo(stderr, QStringLiteral("stepdeck-sim: %1").arg(reason));
        QCoreApplication::exit(1);
    });
    endpoint.open(model->line);
    simulator->attach(&endpoint);

    // First line, flushed: the contract with tests and scripts.
    printTo(stdout, endpoint.slavePath());
    printTo(stderr,
            simapp::SimText::tr("stepdeck-sim: %1 (%2) on %3%4; SIGINT/SIGTERM to quit")
                .arg(model->id, model->displayName, endpoint.slavePath(),
                     scenario.pace
                         ? simapp::SimText::tr(", paced at %1 baud").arg(model->line.baudRate)
                         : QString()));

    const stepdeck::app::SignalPipe signalPipe([](int) { QCoreApplication::quit(); });
    const int code = application.exec();
    delete simulator; // before the endpoint it is connected to
    return code;
}
