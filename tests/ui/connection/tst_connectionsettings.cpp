// What the connection bar remembers and restores (issues 7 and 10): the reset line per model
// (reaching the controller like the CLI's --reset-line), the recent ports, model, port, poll
// interval and window layout across a restart, and auto-reconnect to a USB device that came
// back -- positions unknown, nothing resumed, the operator told. Settings are isolated
// (QStandardPaths test mode): the user's files are never touched.
#include "../UiTestSupport.h"
#include "TestMain.h"
#include "connection/ConnectionSettings.h"
#include "connection/PortScanner.h"
#include "connection/PortWatcher.h"
#include "jog/JogPanel.h"
#include "protocols/elab/ElabCodec.h"
#include "sim/PtyEndpoint.h"
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>

using namespace stepdeck;
using namespace stepdeck::test;
namespace cs = stepdeck::ui::connectionsettings;

namespace {
// A device on a pseudo-terminal that records every byte it receives.
struct PtyDevice
{
    std::unique_ptr<PtyEndpoint> pty = std::make_unique<PtyEndpoint>();
    std::unique_ptr<elab::ElabSimulator> sim;
    QByteArray received;

    // setUp: the board's ramp setup already written (motion allowed), as after a replug of
    // the USB adapter alone: the board itself kept its power.
    bool start(bool setUp = false)
    {
        SimulatorOptions options;
        options.line = findModel(QStringLiteral("elab"))->line;
        sim = std::make_unique<elab::ElabSimulator>(options);
        if (setUp) { // through the protocol, before the host is attached (its ACKs go nowhere)
            using namespace elab;
            const Triple<quint16> start{100, 100, 100};
            const Triple<quint16> max{5000, 5000, 5000};
            const Triple<quint16> accel{1000, 1000, 1000};
            sim->receive(encode::ramp(RampKind::StartSpeed, start) +
                         encode::ramp(RampKind::MaxSpeed, max) +
                         encode::ramp(RampKind::Acceleration, accel));
        }
        QSignalSpy opened(pty.get(), &Transport::opened);
        pty->open(options.line);
        if (!opened.wait(2000))
            return false;
        sim->attach(pty.get());
        QObject::connect(pty.get(), &Transport::dataReceived, pty.get(),
                         [this](const QByteArray& bytes) { received += bytes; });
        return true;
    }
    QList<char> motionCodes() const
    {
        using namespace elab::ctrl;
        const QList<char> motion{EOT, BS, FF, VT, DC2, DC4, CAN, EM, SUB, US};
        QList<char> out;
        elab::CommandDecoder decoder;
        for (const elab::Command& c : decoder.feed(received)) {
            // A jog speed of zero everywhere is a stop, not motion.
            const bool zeroJog = c.code == DC4 && c.values == std::array<qint64, 3>{};
            if (motion.contains(c.code) && !zeroJog)
                out << c.code;
        }
        return out;
    }
};

// The port list the fake scanner returns (read in the scanner's thread).
struct FakePorts
{
    QMutex mutex;
    QList<ui::PortEntry> ports;
    void set(const QList<ui::PortEntry>& list)
    {
        QMutexLocker lock(&mutex);
        ports = list;
    }
};

ui::PortEntry usbEntry(const QString& path)
{
    ui::PortEntry e;
    e.path = path;
    e.label = path + QStringLiteral(" (0403:6001)");
    e.usb = true;
    e.vendorId = 0x0403;
    e.productId = 0x6001;
    e.serialNumber = QStringLiteral("A10K7XYZ");
    return e;
}
} // namespace

class TestConnectionSettings : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init() { QSettings().clear(); }

    void resetLine_dtrChosen_reachesController_rememberedPerModel();
    void resetLine_onlyForModelsWithOne();
    void recentPorts_mostRecentFirst_bounded();
    void connect_addsPortToRecentMenuAndCombo();
    void restart_restoresModelPortIntervalAndLayout();
    void usbDeviceBack_reconnects_unreferenced_nothingResumed();
    void operatorDisconnect_deviceBack_staysDisconnected();

private:
    bool rescanned(ui::ConnectionBar* bar);
};

bool TestConnectionSettings::rescanned(ui::ConnectionBar* bar)
{
    QSignalSpy scanned(bar->portScanner(), &ui::PortScanner::scanned);
    bar->portScanner()->rescan();
    return scanned.wait(3000);
}

void TestConnectionSettings::resetLine_dtrChosen_reachesController_rememberedPerModel()
{
    {
        UiFixture f;
        ui::ConnectionBar* bar = f.window->connectionBar();
        bar->setSelectedModel(QStringLiteral("elab"));
        QComboBox* line = bar->resetLineCombo();
        QCOMPARE(line->currentData().toString(), QStringLiteral("rts")); // the manual's text
        line->setCurrentIndex(line->findData(QStringLiteral("dtr")));
        Q_EMIT line->activated(line->currentIndex());
        QVERIFY(f.connectSim());
        QCOMPARE(f.session->spec().options.resetLine, LineSettings::ResetLine::Dtr);
        // What the adapter opened its transport with.
        LineSettings::ResetLine opened = LineSettings::ResetLine::Rts;
        QVERIFY(f.withSim([&opened](elab::ElabSimulator* sim) {
            const Controller* c = sim->parent()->findChild<Controller*>();
            if (auto* t = qobject_cast<LoopbackTransport*>(c->transport()))
                opened = t->lineSettings().resetLine;
        }));
        QCOMPARE(opened, LineSettings::ResetLine::Dtr);
        QVERIFY(!line->isEnabled()); // not changed under an open link
    }
    QCOMPARE(cs::resetLine(QStringLiteral("elab")), LineSettings::ResetLine::Dtr);
    QCOMPARE(cs::resetLine(QStringLiteral("nanotec")), LineSettings::ResetLine::Rts);
    UiFixture again;
    again.window->connectionBar()->setSelectedModel(QStringLiteral("elab"));
    QCOMPARE(again.window->connectionBar()->resetLineCombo()->currentData().toString(),
             QStringLiteral("dtr"));
}

void TestConnectionSettings::resetLine_onlyForModelsWithOne()
{
    UiFixture f;
    ui::ConnectionBar* bar = f.window->connectionBar();
    for (const ModelInfo& model : models()) {
        bar->setSelectedModel(model.id);
        QCOMPARE(bar->resetLineCombo()->isHidden(), !model.capabilities.resetLine);
    }
    bar->setSelectedModel(QStringLiteral("elab"));
    QVERIFY(!bar->resetLineCombo()->isHidden());
}

void TestConnectionSettings::recentPorts_mostRecentFirst_bounded()
{
    QVERIFY(cs::recentPorts().isEmpty());
    for (int i = 0; i < cs::kMaxRecentPorts + 3; ++i)
        cs::addRecentPort(QStringLiteral("/dev/ttyUSB%1").arg(i));
    cs::addRecentPort(QStringLiteral("/dev/ttyUSB9")); // used again: to the front, once
    const QStringList recent = cs::recentPorts();
    QCOMPARE(recent.size(), cs::kMaxRecentPorts);
    QCOMPARE(recent.first(), QStringLiteral("/dev/ttyUSB9"));
    QCOMPARE(recent.at(1), QStringLiteral("/dev/ttyUSB10"));
    QCOMPARE(recent.count(QStringLiteral("/dev/ttyUSB9")), 1);
    QVERIFY(!recent.contains(QStringLiteral("/dev/ttyUSB0"))); // the oldest dropped
}

void TestConnectionSettings::connect_addsPortToRecentMenuAndCombo()
{
    PtyDevice device;
    QVERIFY(device.start());
    const QString path = device.pty->slavePath();
    {
        UiFixture f;
        ui::ConnectionBar* bar = f.window->connectionBar();
        bar->setSelectedModel(QStringLiteral("elab"));
        bar->setPortSpec(path);
        bar->connectNow();
        QVERIFY(f.waitConnected());
        QCOMPARE(cs::recentPorts().value(0), path);
        bar->disconnectNow();
        QTRY_VERIFY(!f.window->context()->isConnected());
        QVERIFY(f.connectSim());
        QCOMPARE(cs::recentPorts(), (QStringList{QStringLiteral("sim"), path}));
    }
    UiFixture next;
    ui::ConnectionBar* bar = next.window->connectionBar();
    QVERIFY(bar->portCombo()->findData(path) >= 0); // a pty the scan cannot list
    Q_EMIT bar->recentPortsMenu()->aboutToShow();
    const QList<QAction*> actions = bar->recentPortsMenu()->actions();
    QCOMPARE(actions.size(), 2);
    QCOMPARE(actions.at(0)->data().toString(), QStringLiteral("sim"));
    actions.at(1)->trigger();
    QCOMPARE(bar->portSpec(), path);
}

void TestConnectionSettings::restart_restoresModelPortIntervalAndLayout()
{
    {
        UiFixture f;
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        ui::ConnectionBar* bar = f.window->connectionBar();
        bar->findChild<QSpinBox*>()->setValue(125);
        bar->setSelectedModel(QStringLiteral("emis"));
        bar->setPortSpec(QStringLiteral("sim"));
        bar->connectNow();
        QVERIFY(f.waitConnected());
        f.window->findChild<QDockWidget*>(QStringLiteral("positionDock"))->hide();
        f.window->close(); // saves geometry and state
    }
    UiFixture f;
    ui::ConnectionBar* bar = f.window->connectionBar();
    QCOMPARE(bar->selectedModelId(), QStringLiteral("emis"));
    QCOMPARE(bar->portSpec(), QStringLiteral("sim"));
    QCOMPARE(bar->findChild<QSpinBox*>()->value(), 125);
    f.window->show();
    QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
    QVERIFY(f.window->findChild<QDockWidget*>(QStringLiteral("positionDock"))->isHidden());
    QVERIFY(!f.window->findChild<QDockWidget*>(QStringLiteral("statusDock"))->isHidden());
}

void TestConnectionSettings::usbDeviceBack_reconnects_unreferenced_nothingResumed()
{
    auto first = std::make_unique<PtyDevice>();
    QVERIFY(first->start(true));
    FakePorts fake;
    fake.set({usbEntry(first->pty->slavePath())});
    UiFixture f;
    ui::ConnectionBar* bar = f.window->connectionBar();
    QVERIFY(bar->autoReconnectAction()->isChecked()); // default on
    bar->portScanner()->setScanFunction([&fake] {
        QMutexLocker lock(&fake.mutex);
        return fake.ports;
    });
    QVERIFY(rescanned(bar));
    bar->setSelectedModel(QStringLiteral("elab"));
    bar->setPortSpec(first->pty->slavePath());
    bar->connectNow();
    QVERIFY(f.waitConnected());
    QTRY_VERIFY(bar->portWatcher()->isWatching());
    // The operator jogs X with the keyboard and keeps the key held through it all.
    f.window->show();
    QVERIFY(QTest::qWaitForWindowActive(f.window.get()));
    f.window->jogPanel()->keyboardCheck()->setChecked(true);
    QTest::keyPress(f.window.get(), Qt::Key_Right);
    KeyRepeater held(Qt::Key_Right);
    held.start();
    QTRY_VERIFY_WITH_TIMEOUT(first->sim->isMoving(Axis::X), 3000); // jogging works here

    // Unplugged: the port vanishes, the scan no longer lists it.
    first->pty->vanish();
    fake.set({});
    QTRY_VERIFY_WITH_TIMEOUT(!f.window->context()->isConnected(), 3000);
    QVERIFY(rescanned(bar));
    QVERIFY(bar->portWatcher()->isGone());

    // Plugged in again: the same adapter under another path.
    PtyDevice second;
    QVERIFY(second.start(true));
    fake.set({usbEntry(second.pty->slavePath())});
    QVERIFY(rescanned(bar));
    QVERIFY(f.waitConnected());
    QCOMPARE(f.window->context()->portName(), second.pty->slavePath());
    QVERIFY(f.window->lastError().contains(QStringLiteral("Reconnected")));
    QVERIFY(f.window->lastError().contains(QStringLiteral("unknown")));
    const int polls = f.statusCount;
    QTRY_VERIFY(f.statusCount > polls + 5); // it polls and nothing else happens
    for (const AxisStatus& axis : f.window->context()->status().axes)
        QVERIFY(!axis.referenced);
    QVERIFY(held.sent() > 0); // the key was held all along
    QCOMPARE(second.motionCodes(), QList<char>{});
    for (Axis axis : {Axis::X, Axis::Y, Axis::Z})
        QVERIFY(!second.sim->isMoving(axis));
    held.stop();
}

void TestConnectionSettings::operatorDisconnect_deviceBack_staysDisconnected()
{
    PtyDevice device;
    QVERIFY(device.start());
    FakePorts fake;
    fake.set({usbEntry(device.pty->slavePath())});
    UiFixture f;
    ui::ConnectionBar* bar = f.window->connectionBar();
    bar->portScanner()->setScanFunction([&fake] {
        QMutexLocker lock(&fake.mutex);
        return fake.ports;
    });
    QVERIFY(rescanned(bar));
    bar->setSelectedModel(QStringLiteral("elab"));
    bar->setPortSpec(device.pty->slavePath());
    bar->connectNow();
    QVERIFY(f.waitConnected());
    QTRY_VERIFY(bar->portWatcher()->isWatching());
    bar->disconnectNow(); // the operator's choice
    QTRY_VERIFY(!f.session->isCreated() || f.session->linkState() == LinkState::Disconnected);
    fake.set({});
    QVERIFY(rescanned(bar));
    fake.set({usbEntry(device.pty->slavePath())});
    QVERIFY(rescanned(bar));
    QVERIFY(rescanned(bar));
    QVERIFY(!f.window->context()->isConnected());
    QCOMPARE(f.session->linkState(), LinkState::Disconnected);
}

STEPDECK_TEST_MAIN(TestConnectionSettings)
#include "tst_connectionsettings.moc"
