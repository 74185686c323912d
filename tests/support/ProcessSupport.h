#pragma once
// End-to-end test helpers: run stepdeck-cli, start stepdeck-sim and read its pty path.
#include <QProcess>
#include <QStringList>
#include <QtDebug>

namespace stepdeck::testing {

struct ProcessRun
{
    int exitCode = -1; // -1: did not finish in time, -2: crashed
    QByteArray out;
    QByteArray err;
};

inline ProcessRun runProcess(const QString& program, const QStringList& args, int timeoutMs)
{
    QProcess process;
    process.start(program, args);
    ProcessRun run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        qWarning() << program << args << "did not finish";
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// Starts stepdeck-sim in `sim` and returns the pseudo-terminal path it prints on its first
// line (the stepdeck-sim contract); empty with *error set when it does not.
inline QString startSimulator(QProcess* sim, const QString& program, const QStringList& args,
                              QString* error)
{
    sim->setStandardErrorFile(QProcess::nullDevice()); // its one "serving on" line
    sim->start(program, args);
    if (!sim->waitForStarted(5000)) {
        *error = sim->errorString();
        return {};
    }
    while (!sim->canReadLine()) {
        if (!sim->waitForReadyRead(5000)) {
            *error = QStringLiteral("stepdeck-sim printed no pty path");
            return {};
        }
    }
    const QString path = QString::fromLocal8Bit(sim->readLine()).trimmed();
    if (!path.startsWith(QLatin1String("/dev/")))
        *error = QStringLiteral("stepdeck-sim printed '%1', not a device path").arg(path);
    return path.startsWith(QLatin1String("/dev/")) ? path : QString();
}

} // namespace stepdeck::testing
