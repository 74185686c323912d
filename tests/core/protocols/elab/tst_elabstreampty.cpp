// The <DC2> stream over a real pseudo-terminal: the E-LAB simulator on the device side, the
// adapter through the real QSerialPort (SerialTransport). A pty reports no output queue
// (TIOCOUTQ is 0) and carries every byte at once, like a USB adapter whose own FIFO the driver
// does not count: only the host's own wire budget keeps the stream from running ahead of the
// line. Asserted at the device: after each of the board's XOFFs at most one chunk arrives.
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/elab/ElabController.h"
#include "protocols/elab/ElabCtlStream.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/elab/ElabSimulator.h"
#include "sim/PtyEndpoint.h"
#include "transport/SerialTransport.h"
#include <QDeadlineTimer>
#include <QtTest>
#include <memory>

using namespace stepdeck;
using namespace stepdeck::elab;

class TestElabStreamPty : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void stream_boardXoffAfter16Pairs_atMostOneChunkMoreArrives();

private:
    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 5000);

    std::unique_ptr<PtyEndpoint> m_device;
    std::unique_ptr<ElabSimulator> m_sim;
    std::unique_ptr<SerialTransport> m_port;
    std::unique_ptr<ElabController> m_ctl;
    RequestId m_nextId = 0;
};

void TestElabStreamPty::init()
{
    m_device = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_device->create(&error), qPrintable(error));
    m_sim = std::make_unique<ElabSimulator>(SimulatorOptions{});
    m_device->open(lineSettings());
    m_sim->attach(m_device.get());
    m_port = std::make_unique<SerialTransport>(m_device->slavePath());
    ControllerOptions co;
    co.pollIntervalMs = 50;
    co.commandTimeoutMs = 1000; // generous: a loaded machine must not see false timeouts
    m_ctl = std::make_unique<ElabController>(m_port.get(), co);
    CommandResult r = run([this](RequestId id) { m_ctl->openLink(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    auto perAxis = [](qint64 v) {
        ParameterValue p;
        p.perAxis = {{Axis::X, v}, {Axis::Y, v}, {Axis::Z, v}};
        return p;
    };
    ParameterSet set;
    set.insert("start-speed", perAxis(3000));
    set.insert("max-speed", perAxis(5000));
    set.insert("acceleration", perAxis(20000));
    set.insert("feed-speed", perAxis(1000)); // the board drains slower than the line fills
    r = run([&](RequestId id) { m_ctl->writeParameters(id, set, false); });
    QVERIFY2(r.ok(), qPrintable(r.message));
}

void TestElabStreamPty::cleanup()
{
    m_ctl.reset();
    m_port.reset();
    m_sim.reset();
    m_device.reset();
}

CommandResult TestElabStreamPty::run(const std::function<void(RequestId)>& call, int timeoutMs)
{
    const RequestId id = ++m_nextId;
    QSignalSpy spy(m_ctl.get(), &Controller::requestFinished);
    call(id);
    auto find = [&]() -> std::optional<CommandResult> {
        for (const auto& args : spy) {
            const auto r = args.at(0).value<CommandResult>();
            if (r.id == id)
                return r;
        }
        return std::nullopt;
    };
    QDeadlineTimer deadline(timeoutMs);
    while (!find() && !deadline.hasExpired())
        spy.wait(20);
    return find().value_or(CommandResult::failure(id, ErrorKind::Timeout, "test: no result"));
}

// The audit's peer: XOFF once 16 pairs wait in the buffer, XON at 8. The manual leaves the
// buffer's size and marks to the board ("Da der Buffer des Controllers meistens eine komplexe
// Figur nicht als ganzes aufnehmen kann, stoppt der Controller den Datenfluss ... mit <XOFF>").
void TestElabStreamPty::stream_boardXoffAfter16Pairs_atMostOneChunkMoreArrives()
{
    m_sim->setStreamBuffer(256, 16, 8);
    const int total = 300;
    const QVector<AxisVector> steps(total, AxisVector{{Axis::X, 1}, {Axis::Z, -1}});
    QSignalSpy traffic(m_ctl.get(), &Controller::traffic);
    const CommandResult r = run([&](RequestId id) { m_ctl->feedStream(id, steps); }, 30000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(m_sim->standingStill(), 10000);
    QVERIFY2(m_sim->streamMostPairsAfterXOff() <= ElabCtlStream::kChunkSteps,
             qPrintable(QString::number(m_sim->streamMostPairsAfterXOff())));
    // The board did throttle the host, and nothing was lost or refused.
    int xoffs = 0;
    for (const QList<QVariant>& args : traffic) {
        const auto rec = args.at(0).value<TrafficRecord>();
        xoffs +=
            rec.direction == TrafficRecord::Direction::In && rec.bytes == QByteArray(1, ctrl::XOFF)
                ? 1
                : 0;
    }
    QVERIFY2(xoffs >= 2, qPrintable(QString::number(xoffs)));
    QCOMPARE(m_sim->streamOverflows(), 0);
    QCOMPARE(m_sim->streamRejected(), 0);
    QCOMPARE(m_sim->executedStepBytes(), total);
    QCOMPARE(m_sim->position(Axis::X), total);
    QCOMPARE(m_sim->position(Axis::Z), -total);
}

STEPDECK_TEST_GUILESS_MAIN(TestElabStreamPty)
#include "tst_elabstreampty.moc"
