// stepdeck-cli: the technicians' scripting interface (issue #2, section 5; docs/cli.md).
#include "CliArguments.h"
#include "CliCommands.h"
#include "CliMachineRun.h"
#include "CliOutput.h"
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

    if (!options.machineFile.isEmpty())
        return runWithMachine(options);
    return runSingleController(options);
}
