// Peer vanishes (issue #2, section 6): the pty master closes under a connected adapter -- the
// USB adapter pulled mid-move. Expected: one error report, port closed, link Lost, nothing
// pending left unfinished, no crash, and quiet afterwards (Qt 6.4 would spin on ReadError).
#include "TestMain.h"
#include "TestSupport.h"
#include "controller/Controller.h"
#include "controller/ControllerSession.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/elab/ElabSimulator.h"
#include "sim/PtyEndpoint.h"
#include "transport/SerialTransport.h"
#include <QtTest>
#include <memory>

using namespace stepdeck;

namespace {
enum class Scenario { Idle, MidMove, MidStream, RequestInFlight };

constexpr RequestId kOpen = 1, kSetup = 2, kAction = 3, kAfter = 4;

ParameterSet rampSetup()
{
    auto perAxis = [](qint64 v) {
        ParameterValue value;
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            value.perAxis.insert(a, v);
        return value;
    };
    return ParameterSet{{"start-speed", perAxis(100)},
                        {"max-speed", perAxis(1000)},
                        {"acceleration", perAxis(500)},
                        {"feed-speed", perAxis(50)}};
}

int countFinished(const QSignalSpy& spy, RequestId id)
{
    int n = 0;
    for (const QList<QVariant>& args : spy)
        n += args.at(0).value<CommandResult>().id == id ? 1 : 0;
    return n;
}

CommandResult finished(const QSignalSpy& spy, RequestId id)
{
    for (const QList<QVariant>& args : spy) {
        const CommandResult r = args.at(0).value<CommandResult>();
        if (r.id == id)
            return r;
    }
    return {};
}

int countLinkState(const QSignalSpy& spy, LinkState state)
{
    int n = 0;
    for (const QList<QVariant>& args : spy)
        n += args.at(0).value<LinkState>() == state ? 1 : 0;
    return n;
}
} // namespace

Q_DECLARE_METATYPE(Scenario)

class TestPeerVanish : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void peerVanishes_reportsOnceClosesPortAndStaysQuiet_data();
    void peerVanishes_reportsOnceClosesPortAndStaysQuiet();
    void peerVanishes_throughSession_linkLostReportedOnce();

private:
    std::unique_ptr<PtyEndpoint> m_device;
    std::unique_ptr<elab::ElabSimulator> m_sim;
};

void TestPeerVanish::init()
{
    qRegisterMetaType<CommandResult>();
    qRegisterMetaType<LinkState>();
    m_device = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_device->create(&error), qPrintable(error));
    SimulatorOptions options;
    options.line = elab::lineSettings();
    m_sim = std::make_unique<elab::ElabSimulator>(options);
    m_sim->attach(m_device.get());
}

void TestPeerVanish::cleanup()
{
    m_sim.reset();
    m_device.reset();
}

void TestPeerVanish::peerVanishes_reportsOnceClosesPortAndStaysQuiet_data()
{
    QTest::addColumn<Scenario>("scenario");
    QTest::newRow("idle") << Scenario::Idle;
    QTest::newRow("mid-move") << Scenario::MidMove;
    QTest::newRow("mid-DC2-stream") << Scenario::MidStream;
    QTest::newRow("request in flight") << Scenario::RequestInFlight;
}

void TestPeerVanish::peerVanishes_reportsOnceClosesPortAndStaysQuiet()
{
    QFETCH(Scenario, scenario);
    const ModelInfo* model = findModel("elab");
    QVERIFY(model);
    SerialTransport transport(m_device->slavePath());
    std::unique_ptr<Controller> controller(model->createController(&transport, {}));
    QSignalSpy results(controller.get(), &Controller::requestFinished);
    QSignalSpy links(controller.get(), &Controller::linkStateChanged);
    QSignalSpy errors(controller.get(), &Controller::errorOccurred);
    QSignalSpy traffic(controller.get(), &Controller::traffic);
    QSignalSpy failed(&transport, &Transport::failed);

    controller->openLink(kOpen);
    QTRY_COMPARE_WITH_TIMEOUT(controller->linkState(), LinkState::Connected, 5000);
    controller->writeParameters(kSetup, rampSetup(), false);
    QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, kSetup), 1, 5000);
    QVERIFY2(finished(results, kSetup).ok(), qPrintable(finished(results, kSetup).message));

    switch (scenario) {
    case Scenario::Idle:
        break;
    case Scenario::MidMove:
        controller->moveRelative(kAction, AxisVector{{Axis::X, 200000}});
        QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, kAction), 1, 5000);
        QVERIFY2(finished(results, kAction).ok(), qPrintable(finished(results, kAction).message));
        QTRY_VERIFY_WITH_TIMEOUT(controller->status().axes.value(Axis::X).moving, 5000);
        QVERIFY(m_sim->isMoving(Axis::X));
        break;
    case Scenario::MidStream:
        controller->feedStream(kAction, QVector<AxisVector>(100000, AxisVector{{Axis::X, 1}}));
        QTRY_VERIFY_WITH_TIMEOUT(m_sim->streamBuffered() > 0 || m_sim->executedStepBytes() > 0,
                                 5000);
        break;
    case Scenario::RequestInFlight:
        controller->refreshStatus(kAction); // its exchanges are on the wire when the pty goes
        break;
    }
    const qsizetype errorsBefore = errors.count();

    m_device->vanish();
    QTRY_COMPARE_WITH_TIMEOUT(controller->linkState(), LinkState::Lost, 3000);
    // Let the event loop run: a transport left open would now spin on ReadError.
    QTest::qWait(300);
    const qsizetype trafficAfterLoss = traffic.count();
    QVERIFY(test::staysQuiet(traffic, 200)); // no polls, no writes, no reads after the loss

    QCOMPARE(failed.count(), 1);
    QVERIFY(!transport.isOpen());
    QCOMPARE(errors.count() - errorsBefore, 1);
    QCOMPARE(countLinkState(links, LinkState::Lost), 1);
    QCOMPARE(controller->status().commFault, true);
    QCOMPARE(traffic.count(), trafficAfterLoss);
    if (scenario != Scenario::Idle)
        QCOMPARE(countFinished(results, kAction), 1); // finished, and only once
    if (scenario == Scenario::MidStream)
        QCOMPARE(finished(results, kAction).error, ErrorKind::LinkDown);
    // After a loss nothing is referenced (issue #2, section 2).
    for (const AxisStatus& axis : controller->status().axes)
        QVERIFY(!axis.positionKnown);

    // A command after the loss fails cleanly instead of touching a dead port.
    controller->refreshStatus(kAfter);
    QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, kAfter), 1, 2000);
    QCOMPARE(finished(results, kAfter).error, ErrorKind::LinkDown);
    QCOMPARE(failed.count(), 1);
    controller.reset(); // before the transport it points at
}

void TestPeerVanish::peerVanishes_throughSession_linkLostReportedOnce()
{
    // The same through ControllerSession: the adapter in its own thread, reports queued.
    ControllerSession session;
    ConnectionSpec spec;
    spec.port = m_device->slavePath();
    QString error;
    QVERIFY2(session.create(*findModel("elab"), spec, &error), qPrintable(error));
    QSignalSpy links(&session, &ControllerSession::linkStateChanged);
    QSignalSpy errors(&session, &ControllerSession::errorOccurred);
    QSignalSpy results(&session, &ControllerSession::requestFinished);
    session.open();
    QTRY_COMPARE_WITH_TIMEOUT(session.linkState(), LinkState::Connected, 5000);
    const RequestId setup = session.writeParameters(rampSetup(), false);
    QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, setup), 1, 5000);
    const RequestId move = session.moveRelative(AxisVector{{Axis::Y, 200000}});
    QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, move), 1, 5000);
    QVERIFY(finished(results, move).ok());
    QTRY_VERIFY_WITH_TIMEOUT(session.status().axes.value(Axis::Y).moving, 5000);

    m_device->vanish();
    QTRY_COMPARE_WITH_TIMEOUT(session.linkState(), LinkState::Lost, 3000);
    QTest::qWait(300);
    QCOMPARE(countLinkState(links, LinkState::Lost), 1);
    QCOMPARE(errors.count(), 1);
    QVERIFY(session.status().commFault);
    const RequestId after = session.refreshStatus();
    QTRY_COMPARE_WITH_TIMEOUT(countFinished(results, after), 1, 2000);
    QCOMPARE(finished(results, after).error, ErrorKind::LinkDown);
    session.destroy(); // no crash tearing down a stack whose port is gone
    QCOMPARE(errors.count(), 1);
}

STEPDECK_TEST_GUILESS_MAIN(TestPeerVanish)
#include "tst_peer_vanish.moc"
