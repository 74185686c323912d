// One invocation with --model/--port: its session, its signals, its exit code.
#include "../common/SignalPipe.h"
#include "CliCommands.h"
#include "CliMachineRun.h"
#include "CliText.h"

namespace stepdeck::cli {

int runSingleController(const CliOptions& options)
{
    if (runsOnTheMachine(options))
        return runOneControllerMachine(options);
    CliSession session(options);
    const app::SignalPipe signalPipe([&session](int) { session.interrupt(); });

    CliContext context{options, findModel(options.model), session};
    Outcome outcome = runCommand(context);
    if (session.interrupted()) {
        // Ramped stop, then exit 130; the line says whether the controller confirmed it.
        const bool connected = session.isConnected();
        const Outcome stopped = session.stopMotion();
        const QString text = !connected ? CliText::tr("interrupted")
                             : stopped.ok()
                                 ? CliText::tr("interrupted: the controller acknowledged the stop")
                                 : CliText::tr("interrupted: %1").arg(stopped.message);
        outcome = Outcome::failure(ExitInterrupted, text);
    }
    if (!outcome.ok())
        printError(outcome.message);
    return outcome.code;
}

} // namespace stepdeck::cli
