#pragma once
// Shared set-up of the GUI tests: a MainWindow with a fake gamepad, connected to the
// in-process E-LAB simulator through the ControllerSession, and the traffic it produced.
#include "FakeGamepadDevice.h"
#include "TestSupport.h"
#include "connection/ConnectionBar.h"
#include "controller/Controller.h"
#include "machine/MachineContext.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "transport/LoopbackTransport.h"
#include "window/MainWindow.h"
#include <QApplication>
#include <QFileInfo>
#include <QMutex>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include <atomic>
#include <memory>

namespace stepdeck::test {

// Settings of a test run never touch the user's and start empty. One settings file per test
// executable: ctest runs UI tests in parallel, and a shared file let one test's connection
// overwrite another's remembered ports.
inline void isolateSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    // Per test: tests run side by side (ctest -j). The application's name, not its file: the
    // tests of a group share one program, whose main gives each test its own name as argv[0]
    // (tests/support/TestGroupMain.cpp), which Qt's default application name is taken from.
    const QString prefix = QStringLiteral("StepDeckUiTest-");
    if (!QCoreApplication::applicationName().startsWith(prefix)) // once per process
        QCoreApplication::setApplicationName(prefix + QCoreApplication::applicationName());
    QSettings().clear();
}

class UiFixture
{
public:
    UiFixture()
    {
        gamepad = new FakeGamepadDevice;
        window = std::make_unique<ui::MainWindow>(gamepad);
        session = window->context()->session();
        QObject::connect(session, &ControllerSession::traffic, session,
                         [this](const TrafficRecord& r) { records.append(r); });
        QObject::connect(session, &ControllerSession::statusChanged, session,
                         [this](const MachineStatus&) { ++statusCount; });
    }

    // Connects through the connection bar to the in-process simulator, and records every
    // byte the simulated device receives (deviceBytes()).
    bool connectSim()
    {
        window->connectionBar()->setSelectedModel(QStringLiteral("elab"));
        window->connectionBar()->setPortSpec(QStringLiteral("sim"));
        window->connectionBar()->connectNow();
        return waitConnected() && recordDevice();
    }

    // Connected, and the E-LAB ramp setup written (the board refuses motion without it).
    bool connectAndSetUp()
    {
        if (!connectSim())
            return false;
        QSignalSpy done(session, &ControllerSession::requestFinished);
        const RequestId id = writeRampSetup();
        for (int i = 0; i < 100; ++i) {
            for (const QList<QVariant>& args : done) {
                const CommandResult r = args.at(0).value<CommandResult>();
                if (r.id == id)
                    return r.ok();
            }
            done.wait(50);
        }
        return false;
    }

    // Taps the device end of the in-process link: what the simulator really received (after
    // any discardOutput()), in the controller thread.
    bool recordDevice()
    {
        auto device = m_device;
        return withSimulatorAs<Simulator>([device](Simulator* sim) {
            QObject* stack = sim->parent();
            const Controller* controller = stack->findChild<Controller*>();
            for (LoopbackTransport* end : stack->findChildren<LoopbackTransport*>()) {
                if (controller && end == controller->transport())
                    continue;
                QObject::connect(
                    end, &Transport::dataReceived, end,
                    [device](const QByteArray& bytes) {
                        QMutexLocker lock(&device->mutex);
                        device->bytes += bytes;
                    },
                    Qt::DirectConnection);
            }
        });
    }

    QByteArray deviceBytes() const
    {
        QMutexLocker lock(&m_device->mutex);
        return m_device->bytes;
    }
    qsizetype deviceMark() const { return deviceBytes().size(); }

    // Commands with the given code the device received since `mark`, decoded, in order.
    QList<elab::Command> deviceCommands(char code, qsizetype mark = 0) const
    {
        elab::CommandDecoder decoder;
        QList<elab::Command> out;
        for (const elab::Command& c : decoder.feed(deviceBytes().mid(mark)))
            if (c.code == code)
                out << c;
        return out;
    }

    struct SimAxis
    {
        bool moving = false;
        qint64 position = 0;
    };
    SimAxis simAxis(Axis axis)
    {
        SimAxis out;
        withSim([&out, axis](elab::ElabSimulator* sim) {
            out.moving = sim->isMoving(axis);
            out.position = sim->position(axis);
        });
        return out;
    }

    // The simulated axis has stopped, and stays where it stopped over `polls` further status
    // rounds. False (with the reason in *why) otherwise.
    bool simStandsStill(Axis axis, int polls, QString* why)
    {
        QElapsedTimer t;
        t.start();
        while (simAxis(axis).moving && t.elapsed() < 5000)
            QTest::qWait(10);
        const SimAxis stopped = simAxis(axis);
        if (stopped.moving) {
            *why = QStringLiteral("axis %1 still moving after 5 s").arg(axisName(axis));
            return false;
        }
        const int from = statusCount;
        while (statusCount - from < polls && t.elapsed() < 15000)
            QTest::qWait(10);
        const SimAxis later = simAxis(axis);
        if (later.moving || later.position != stopped.position) {
            *why = QStringLiteral("axis %1 moved again: %2 -> %3")
                       .arg(axisName(axis))
                       .arg(stopped.position)
                       .arg(later.position);
            return false;
        }
        return true;
    }

    // 15 s: a wait, not a measure; widget tests under ASan+UBSan on a loaded CI machine have
    // needed more than 5 s to connect.
    bool waitConnected(int timeoutMs = 15000)
    {
        QElapsedTimer t;
        t.start();
        while (!window->context()->isConnected() && t.elapsed() < timeoutMs)
            QTest::qWait(10);
        return window->context()->isConnected();
    }

    // Start/max speed, acceleration, feed speed: without them the board refuses motion.
    RequestId writeRampSetup(qint64 maxSpeed = 3000, qint64 acceleration = 2000)
    {
        auto perAxis = [](qint64 v) {
            ParameterValue value;
            for (Axis a : {Axis::X, Axis::Y, Axis::Z})
                value.perAxis.insert(a, v);
            return value;
        };
        const ParameterSet set{{QStringLiteral("start-speed"), perAxis(100)},
                               {QStringLiteral("max-speed"), perAxis(maxSpeed)},
                               {QStringLiteral("acceleration"), perAxis(acceleration)},
                               {QStringLiteral("feed-speed"), perAxis(50)}};
        return window->context()->writeParameters(set, false); // known to the UI afterwards
    }

    // Runs fn on the in-process simulator (of type Sim) in the controller thread and waits,
    // running the event loop, until it ran.
    template <typename Sim> bool withSimulatorAs(std::function<void(Sim*)> fn)
    {
        auto done = std::make_shared<std::atomic_bool>(false);
        session->withSimulator([fn, done](Simulator* s) {
            fn(static_cast<Sim*>(s));
            *done = true;
        });
        QElapsedTimer t;
        t.start();
        while (!*done && t.elapsed() < 5000)
            QTest::qWait(5);
        return *done;
    }

    bool withSim(std::function<void(elab::ElabSimulator*)> fn)
    {
        return withSimulatorAs<elab::ElabSimulator>(std::move(fn));
    }

    // Host -> device bytes of everything recorded since `from` (poll traffic excluded).
    QByteArray sent(qsizetype from = 0, bool includePolls = false) const
    {
        QByteArray out;
        for (qsizetype i = from; i < records.size(); ++i) {
            const TrafficRecord& r = records.at(i);
            if (r.direction == TrafficRecord::Direction::Out && (includePolls || !r.poll))
                out += r.bytes;
        }
        return out;
    }

    // Decoded host commands with the given control code, in order.
    QList<elab::Command> commands(char code, qsizetype from = 0) const
    {
        elab::CommandDecoder decoder;
        QList<elab::Command> out;
        for (const elab::Command& c : decoder.feed(sent(from)))
            if (c.code == code)
                out << c;
        return out;
    }

    double commanded(Axis axis) const
    {
        return window->context()->status().axes.value(axis).commandedVelocity;
    }

    FakeGamepadDevice* gamepad; // owned by the window
    std::unique_ptr<ui::MainWindow> window;
    ControllerSession* session;
    QList<TrafficRecord> records;
    int statusCount = 0;

private:
    struct DeviceLog
    {
        QMutex mutex;
        QByteArray bytes;
    };
    std::shared_ptr<DeviceLog> m_device = std::make_shared<DeviceLog>();
};

// Real pointer input through the window system (QGuiApplication::mouseButtons() follows it,
// as it does for a physical mouse); positions are in w's coordinates.
inline void pointerPress(QWidget* w, const QPointF& pos)
{
    QTest::mousePress(w->window()->windowHandle(), Qt::LeftButton, Qt::NoModifier,
                      w->mapTo(w->window(), pos.toPoint()));
}
inline void pointerMove(QWidget* w, const QPointF& pos)
{
    QTest::mouseMove(w->window()->windowHandle(), w->mapTo(w->window(), pos.toPoint()));
}
inline void pointerRelease(QWidget* w, const QPointF& pos)
{
    QTest::mouseRelease(w->window()->windowHandle(), Qt::LeftButton, Qt::NoModifier,
                        w->mapTo(w->window(), pos.toPoint()));
}
inline void pointerClick(QWidget* w)
{
    QTest::mouseClick(w->window()->windowHandle(), Qt::LeftButton, Qt::NoModifier,
                      w->mapTo(w->window(), w->rect().center()));
}

// A held key as the platform delivers it: auto-repeat presses at 30 Hz to whatever has the
// focus, until stopped. Stopping without a key-up is a lost key-up.
class KeyRepeater : public QObject
{
public:
    explicit KeyRepeater(int key) : m_key(key)
    {
        m_timer.setInterval(33);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] {
            QWidget* target = QApplication::focusWidget();
            if (!target)
                target = QApplication::activeWindow();
            if (!target)
                return;
            QKeyEvent repeat(QEvent::KeyPress, m_key, Qt::NoModifier, QString(), true);
            QApplication::sendEvent(target, &repeat);
            ++m_sent;
        });
    }
    void start() { m_timer.start(); }
    void stop() { m_timer.stop(); }
    int sent() const { return m_sent; }

private:
    int m_key;
    int m_sent = 0;
    QTimer m_timer{this};
};

} // namespace stepdeck::test
