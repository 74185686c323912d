#include "GuiIdle.h"
#include "BenchOutput.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <cstdio>
#include <unistd.h>

namespace stepdeck::bench {

namespace {
struct Options
{
    int seconds = 20;
    int warmupSeconds = 5;
    int pollMs = 50;
    QString platform; // "xvfb" or "offscreen"; empty: xvfb when installed
    bool json = false;
};

bool parse(const QStringList& args, Options* o, QString* error)
{
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args.at(i);
        const bool hasNext = i + 1 < args.size() && !args.at(i + 1).startsWith(QLatin1String("--"));
        bool ok = true;
        if (a == QLatin1String("--gui-idle")) {
            if (hasNext)
                o->seconds = args.at(++i).toInt(&ok, 10);
        } else if (a == QLatin1String("--warmup") && hasNext) {
            o->warmupSeconds = args.at(++i).toInt(&ok, 10);
        } else if (a == QLatin1String("--poll-interval") && hasNext) {
            o->pollMs = args.at(++i).toInt(&ok, 10);
        } else if (a == QLatin1String("--platform") && hasNext) {
            o->platform = args.at(++i);
            ok = o->platform == QLatin1String("xvfb") || o->platform == QLatin1String("offscreen");
        } else if (a == QLatin1String("--json")) {
            o->json = true;
        } else {
            *error = QStringLiteral("--gui-idle: unknown argument '%1'").arg(a);
            return false;
        }
        if (!ok || o->seconds < 1 || o->warmupSeconds < 0 || o->pollMs < 10) {
            *error = QStringLiteral("--gui-idle: bad value for %1").arg(a);
            return false;
        }
    }
    return true;
}

// utime + stime of pid in clock ticks; -1 when the process is gone.
qint64 cpuTicks(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray line = f.readAll();
    // Fields after the command name "(...)", which may contain spaces: state is field 3.
    const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return -1;
    return fields.at(11).toLongLong() + fields.at(12).toLongLong(); // fields 14 and 15
}

// A "Key:   123 kB" line of /proc/<pid>/status (or /proc/<pid>/io without unit), or -1.
qint64 procValue(qint64 pid, const char* file, const QByteArray& key)
{
    QFile f(QStringLiteral("/proc/%1/%2").arg(pid).arg(QLatin1String(file)));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray& line : f.readAll().split('\n')) {
        if (line.startsWith(key + ':'))
            return line.mid(key.size() + 1).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

// Whether an X server listens on display n: its socket, in the file system or (where
// /tmp/.X11-unix cannot be created) in the abstract namespace, is in /proc/net/unix.
bool displayListening(int n)
{
    QFile f(QStringLiteral("/proc/net/unix"));
    const QByteArray socket = "/tmp/.X11-unix/X" + QByteArray::number(n);
    if (!f.open(QIODevice::ReadOnly))
        return QFileInfo::exists(QString::fromLatin1(socket));
    for (const QByteArray& line : f.readAll().split('\n')) {
        if (line.endsWith(socket))
            return true;
    }
    return false;
}

struct Xvfb
{
    QProcess process;
    QString display;

    bool start(QString* error)
    {
        const QString program = QStandardPaths::findExecutable(QStringLiteral("Xvfb"));
        for (int attempt = 0; attempt < 10 && !program.isEmpty(); ++attempt) {
            const int n = 100 + int(QRandomGenerator::global()->bounded(800));
            if (displayListening(n))
                continue;
            process.start(program, {QStringLiteral(":%1").arg(n), QStringLiteral("-screen"),
                                    QStringLiteral("0"), QStringLiteral("1366x768x24"),
                                    QStringLiteral("-nolisten"), QStringLiteral("tcp")});
            process.waitForStarted(3000);
            QElapsedTimer t;
            t.start();
            while (t.elapsed() < 5000 && process.state() == QProcess::Running) {
                if (displayListening(n)) {
                    display = QStringLiteral(":%1").arg(n);
                    return true;
                }
                process.waitForFinished(50);
            }
            process.kill();
            process.waitForFinished(1000);
        }
        *error = QStringLiteral("could not start Xvfb");
        return false;
    }
    ~Xvfb()
    {
        if (process.state() != QProcess::NotRunning) {
            process.terminate();
            if (!process.waitForFinished(3000))
                process.kill();
        }
    }
};

void stop(QProcess& p)
{
    if (p.state() == QProcess::NotRunning)
        return;
    p.terminate();
    if (!p.waitForFinished(5000)) {
        p.kill();
        p.waitForFinished(2000);
    }
}
struct Figures
{
    double seconds = 0;
    double cpuPercent = 0;
    qint64 rssLastKb = 0;
    qint64 rssMaxKb = 0;
    qint64 hwmKb = 0;
    double simBytesPerSecond = 0;
    bool polling = false;
    bool guiAlive = false;
};

// The GUI and the simulator run the first registered model.
const ModelInfo& idleModel()
{
    return models().first();
}

// The first stdout line of stepdeck-sim is its terminal's path.
QString startSimulator(const QString& appDir, QProcess* sim)
{
    sim->start(QDir(appDir).filePath(QStringLiteral("stepdeck-sim")),
               {QStringLiteral("--model"), idleModel().id});
    // Up to 5 s for its first line (the pty's path): a slow start (a sanitized build on a busy
    // machine) is waited for, not taken for a failure at the first 200 ms without output.
    QString ptyPath;
    QElapsedTimer t;
    t.start();
    while (ptyPath.isEmpty() && t.elapsed() < 5000 && sim->state() != QProcess::NotRunning) {
        if (sim->canReadLine())
            ptyPath = QString::fromUtf8(sim->readLine()).trimmed();
        else
            sim->waitForReadyRead(200);
    }
    return ptyPath;
}

bool startGui(const QString& appDir, const Options& o, const QString& ptyPath,
              const QString& configDir, Xvfb* xvfb, QProcess* gui, QString* error)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), configDir); // never the user's settings
    if (o.platform == QLatin1String("xvfb")) {
        if (!xvfb->start(error))
            return false;
        env.insert(QStringLiteral("DISPLAY"), xvfb->display);
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb"));
    } else {
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    }
    gui->setProcessEnvironment(env);
    gui->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    gui->start(QDir(appDir).filePath(QStringLiteral("stepdeck")),
               {QStringLiteral("--model"), idleModel().id, QStringLiteral("--port"), ptyPath,
                QStringLiteral("--poll-interval"), QString::number(o.pollMs)});
    if (!gui->waitForStarted(5000)) {
        *error = QStringLiteral("the GUI did not start");
        return false;
    }
    return true;
}

Figures sample(const Options& o, QProcess* gui, qint64 simPid)
{
    const qint64 guiPid = gui->processId();
    Figures f;
    const qint64 ticks0 = cpuTicks(guiPid);
    const qint64 simRead0 = procValue(simPid, "io", "rchar");
    QElapsedTimer window;
    window.start();
    const qint64 durationMs = qint64(o.seconds) * 1000;
    while (window.elapsed() < durationMs && gui->state() == QProcess::Running) {
        QThread::msleep(quint64(qMin<qint64>(500, durationMs - window.elapsed() + 1)));
        f.rssLastKb = procValue(guiPid, "status", "VmRSS");
        f.rssMaxKb = qMax(f.rssMaxKb, f.rssLastKb);
    }
    f.seconds = window.elapsed() / 1000.0;
    const qint64 ticks1 = cpuTicks(guiPid);
    const qint64 simRead1 = procValue(simPid, "io", "rchar");
    f.hwmKb = procValue(guiPid, "status", "VmHWM");
    f.guiAlive = gui->state() == QProcess::Running && ticks1 >= 0;
    f.cpuPercent = 100.0 * double(ticks1 - ticks0) / double(sysconf(_SC_CLK_TCK)) / f.seconds;
    f.simBytesPerSecond = double(simRead1 - simRead0) / f.seconds;
    f.polling = simRead0 >= 0 && simRead1 > simRead0;
    return f;
}

void report(const Options& o, const Figures& f, const QString& ptyPath)
{
    const QString platform = o.platform == QLatin1String("xvfb")
                                 ? QStringLiteral("Xvfb 1366x768 (xcb)")
                                 : QStringLiteral("offscreen");
    if (o.json) {
        const QJsonObject out{{"guiCpuPercentOfOneCore", f.cpuPercent},
                              {"guiRssMiB", f.rssLastKb / 1024.0},
                              {"guiRssMaxMiB", f.rssMaxKb / 1024.0},
                              {"guiVmHwmMiB", f.hwmKb / 1024.0},
                              {"seconds", f.seconds},
                              {"warmupSeconds", o.warmupSeconds},
                              {"pollIntervalMs", o.pollMs},
                              {"platform", platform},
                              {"simReadBytesPerSecond", f.simBytesPerSecond},
                              {"polling", f.polling}};
        print(stdout, QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Compact)));
        return;
    }
    print(stdout, QStringLiteral("stepdeck-bench --gui-idle: stepdeck on %1, %2 via "
                                 "stepdeck-sim on %3, poll interval %4 ms")
                      .arg(platform, idleModel().displayName, ptyPath)
                      .arg(o.pollMs));
    print(stdout, QStringLiteral("  GUI CPU   %1 % of one core  (utime+stime over %2 s, after "
                                 "%3 s warm-up)")
                      .arg(f.cpuPercent, 0, 'f', 2)
                      .arg(f.seconds, 0, 'f', 1)
                      .arg(o.warmupSeconds));
    print(stdout, QStringLiteral("  GUI RSS   %1 MiB at the end, max %2 MiB (VmHWM %3 MiB)")
                      .arg(f.rssLastKb / 1024.0, 0, 'f', 1)
                      .arg(f.rssMaxKb / 1024.0, 0, 'f', 1)
                      .arg(f.hwmKb / 1024.0, 0, 'f', 1));
    print(stdout, QStringLiteral("  link      simulator read %1 bytes/s%2")
                      .arg(f.simBytesPerSecond, 0, 'f', 0)
                      .arg(f.polling ? QString() : QStringLiteral("  (NOT POLLING)")));
}
} // namespace

int guiIdleMain(const QString& appDir, const QStringList& args)
{
    if (!args.contains(QStringLiteral("--gui-idle")))
        return -1;
    Options o;
    QString error;
    if (!parse(args, &o, &error)) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        return 2;
    }
    if (o.platform.isEmpty())
        o.platform = QStandardPaths::findExecutable(QStringLiteral("Xvfb")).isEmpty()
                         ? QStringLiteral("offscreen")
                         : QStringLiteral("xvfb");
    QProcess sim;
    const QString ptyPath = startSimulator(appDir, &sim);
    if (ptyPath.isEmpty()) {
        print(stderr, QStringLiteral("stepdeck-bench: stepdeck-sim did not start"));
        stop(sim);
        return 1;
    }
    Xvfb xvfb;
    QTemporaryDir config;
    QProcess gui;
    if (!startGui(appDir, o, ptyPath, config.path(), &xvfb, &gui, &error)) {
        print(stderr, QStringLiteral("stepdeck-bench: %1").arg(error));
        stop(sim);
        return 1;
    }
    QThread::msleep(quint64(o.warmupSeconds) * 1000);
    const Figures figures = sample(o, &gui, sim.processId());
    stop(gui);
    stop(sim);
    if (!figures.guiAlive) {
        print(stderr, QStringLiteral("stepdeck-bench: the GUI exited during the measurement"));
        return 1;
    }
    report(o, figures, ptyPath);
    return figures.polling ? 0 : 1;
}

} // namespace stepdeck::bench
