#pragma once
// `stepdeck-cli run` against a simulated controller on a real pty (tst_cli_run,
// tst_cli_run_devices): the device lives in a thread of its own, so the test thread may block
// on the CLI process while the device answers. What the DEVICE did is journaled in its thread:
// every positioning move it accepted, when, and whether that axis was still moving then
// (two motions overlapping on one axis), and when each axis came to rest.
#include "protocols/Registry.h"
#include "sim/PtyEndpoint.h"
#include "sim/Simulator.h"
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <functional>

namespace stepdeck::test {

struct DeviceMove
{
    Axis axis = Axis::X;
    qint64 steps = 0;
    qint64 atMs = 0;         // device clock: when the device accepted it
    bool axisMoving = false; // the axis was still moving when this move came
};

class RunDevice
{
public:
    // addresses: the simulated drives of a multi-drive model (Nanotec), 1 unless given.
    explicit RunDevice(const QString& modelId, const QList<int>& addresses = {1})
        : m_model(findModel(modelId))
    {
        m_thread.start();
        m_home.moveToThread(&m_thread);
        probe([this, addresses] {
            m_end = new PtyEndpoint;
            QString error;
            if (!m_end->create(&error))
                qFatal("pty: %s", qPrintable(error));
            SimulatorOptions options;
            options.line = m_model->line;
            options.addresses = addresses;
            m_sim = m_model->createSimulator(options);
            m_clock.start();
            // Before the simulator sees a frame: the axes as they were; after: what it took.
            QObject::connect(m_end, &Transport::dataReceived, &m_home, [this] { before(); });
            m_sim->attach(m_end);
            QObject::connect(m_end, &Transport::dataReceived, &m_home, [this] { after(); });
            m_sampler = new QTimer(&m_home);
            QObject::connect(m_sampler, &QTimer::timeout, &m_home, [this] { sample(); });
            m_sampler->start(2);
            m_path = m_end->slavePath();
            return true;
        });
    }
    ~RunDevice()
    {
        probe([this] {
            delete m_sampler;
            delete m_sim;
            delete m_end;
            return true;
        });
        m_thread.quit();
        m_thread.wait();
    }
    RunDevice(const RunDevice&) = delete;
    RunDevice& operator=(const RunDevice&) = delete;

    QString path() const { return m_path; }
    Simulator* sim() const { return m_sim; } // only inside probe()
    template <typename F> auto probe(F f) -> decltype(f())
    {
        decltype(f()) result{};
        QMetaObject::invokeMethod(
            &m_home, [&] { result = f(); }, Qt::BlockingQueuedConnection);
        return result;
    }
    // Runs `f` in the device thread after `ms` on the device clock from now.
    void later(int ms, std::function<void(Simulator*)> f)
    {
        probe([&] {
            QTimer::singleShot(ms, &m_home, [this, f] { f(m_sim); });
            return true;
        });
    }
    // Runs `f` in the device thread right after the device accepted its n-th move.
    void afterMove(int n, std::function<void(Simulator*)> f)
    {
        probe([&] {
            m_afterMove = n;
            m_onMove = f;
            return true;
        });
    }

    void vanish() // the USB adapter pulled
    {
        probe([this] {
            m_end->vanish();
            return true;
        });
    }

    QList<DeviceMove> moves()
    {
        return probe([this] { return m_moves; });
    }
    // Device clock, per time X came to rest: the last moment it was still seen moving. The
    // stop lies between that and the next look (a 2 ms timer and every frame received), so
    // `accepted - restTime >= P` never fails on a late timer, and a dwell short by more than
    // one look's gap still fails.
    QList<qint64> restTimes()
    {
        return probe([this] { return m_rests; });
    }
    int receivedCount()
    {
        return probe([this] { return int(m_sim->receivedFrames().size()); });
    }
    bool still()
    {
        return probe([this] { return m_sim->standingStill(); });
    }
    bool moving(Axis axis = Axis::X)
    {
        return probe([&] { return m_sim->isMoving(axis); });
    }
    qint64 position(Axis axis = Axis::X)
    {
        return probe([&] { return m_sim->position(axis); });
    }
    qint64 now()
    {
        return probe([this] { return m_clock.elapsed(); });
    }

private:
    void before()
    {
        sample();
        m_wasMoving.clear();
        for (Axis a : m_model->capabilities.axes)
            m_wasMoving.insert(a, m_sim->isMoving(a));
        m_acceptedBefore = m_sim->acceptedMoves().size();
    }
    void after()
    {
        const QList<SimulatedMove> accepted = m_sim->acceptedMoves();
        for (qsizetype i = m_acceptedBefore; i < accepted.size(); ++i) {
            const SimulatedMove& m = accepted.at(i);
            m_moves.append({m.axis, m.steps, m_clock.elapsed(), m_wasMoving.value(m.axis)});
            if (m_moves.size() == m_afterMove && m_onMove)
                m_onMove(m_sim);
        }
        m_acceptedBefore = accepted.size();
    }
    void sample()
    {
        const bool moving = m_sim->isMoving(Axis::X);
        if (m_xMoving && !moving)
            m_rests.append(m_lastSeenMovingMs);
        if (moving)
            m_lastSeenMovingMs = m_clock.elapsed();
        m_xMoving = moving;
    }

    const ModelInfo* m_model;
    QThread m_thread;
    QObject m_home; // lives in m_thread; everything below is touched only there
    PtyEndpoint* m_end = nullptr;
    Simulator* m_sim = nullptr;
    QTimer* m_sampler = nullptr;
    QElapsedTimer m_clock;
    QHash<Axis, bool> m_wasMoving;
    qsizetype m_acceptedBefore = 0;
    QList<DeviceMove> m_moves;
    QList<qint64> m_rests;
    bool m_xMoving = false;
    qint64 m_lastSeenMovingMs = 0;
    int m_afterMove = -1;
    std::function<void(Simulator*)> m_onMove;
    QString m_path;
};

struct CliRun
{
    int exitCode = -1; // -1: did not finish in time
    QByteArray out;
    QByteArray err;
};

// The CLI for one model on the device's pty. Models that refuse motion until their setup is
// written (E-LAB) get --setup-defaults, the others keep their simulator's values.
inline QStringList cliArgs(const QString& model, const QString& port)
{
    QStringList args{"--model", model, "--port", port, "--timeout", "10000"};
    if (model == QLatin1String("elab"))
        args << "--setup-defaults";
    if (model == QLatin1String("nanotec"))
        args << "--address"
             << "1";
    return args;
}

inline QString cliPath()
{
    return QDir(qEnvironmentVariable("STEPDECK_BIN_DIR")).filePath(QStringLiteral("stepdeck-cli"));
}

inline CliRun runCli(const QStringList& args, int timeoutMs = 60000)
{
    QProcess process;
    process.start(cliPath(), args);
    CliRun run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished(5000);
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// A program file in `dir`: its path.
inline QString writeProgram(const QTemporaryDir& dir, const QString& name, const QByteArray& text)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace stepdeck::test
