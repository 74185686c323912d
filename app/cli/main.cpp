// stepdeck-cli: the technicians' scripting interface (issue #2, section 5; docs/cli.md).
#include "../common/SignalPipe.h"
#include "CliArguments.h"
#include "CliCommands.h"
#include "CliOutput.h"
#include "CliSession.h"
#include "CliText.h"
#include <QCoreApplication>

using namespace stepdeck;
using namespace stepdeck::cli;

namespace {
// Stderr carries exactly one line on failure; the core's warnings only with --verbose or
// QT_LOGGING_RULES.
void quietMessageHandler(QtMsgType type, const QMessageLogContext&, const QString& message)
{
    if (type == QtFatalMsg)
        printError(message);
}
} // namespace

int main(int argc, char** argv)
{
    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stepdeck-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPDECK_VERSION));

    CliOptions options;
    QString error;
    if (!parseArguments(application.arguments(), commandSyntax(), &options, &error)) {
        printError(error);
        return ExitUsage;
    }
    if (options.help) {
        printLine(usageText());
        return ExitOk;
    }
    if (options.version) {
        printLine(QStringLiteral("stepdeck-cli %1").arg(QCoreApplication::applicationVersion()));
        return ExitOk;
    }
    if (!options.verbose && qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        qInstallMessageHandler(quietMessageHandler);

    CliSession session(options);
    const stepdeck::app::SignalPipe signalPipe([&session](int) { session.interrupt(); });

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
