#pragma once
// Shared set-up of the GUI tests: a MainWindow with a fake gamepad, connected to the
// in-process E-LAB simulator through the ControllerSession, and the traffic it produced.
#include "FakeGamepadDevice.h"
#include "TestSupport.h"
#include "main/ConnectionBar.h"
#include "main/MachineContext.h"
#include "main/MainWindow.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>
#include <atomic>
#include <memory>

namespace stepdeck::test {

// Settings of a test run never touch the user's and start empty.
inline void isolateSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckUiTest"));
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

    // Connects through the connection bar to the in-process simulator.
    bool connectSim()
    {
        window->connectionBar()->setSelectedModel(QStringLiteral("elab"));
        window->connectionBar()->setPortSpec(QStringLiteral("sim"));
        window->connectionBar()->connectNow();
        return waitConnected();
    }

    bool waitConnected(int timeoutMs = 5000)
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
        return session->writeParameters(set, false);
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
};

} // namespace stepdeck::test
