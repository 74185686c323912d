// LoopbackTransport: the in-memory pair used by unit tests and the in-process simulator.
#include "TestMain.h"
#include "TestSupport.h"
#include "transport/LoopbackTransport.h"
#include <QtTest>

using namespace stepdeck;

class TestLoopbackTransport : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void open_emitsOpenedQueued();
    void write_arrivesAtPeer_everyByteValue();
    void write_bothDirections_inOrder();
    void write_whenClosed_fails();
    void discardOutput_dropsBytesInFlight();
    void simulateFailure_failedOnceThenClosed();
    void close_emitsClosedOnce();
};

void TestLoopbackTransport::open_emitsOpenedQueued()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    QSignalSpy opened(host, &Transport::opened);
    host->open(LineSettings{});
    QCOMPARE(opened.count(), 0); // asynchronous, like the real transports
    QVERIFY(host->isOpen());
    QVERIFY(opened.wait(1000));
    QCOMPARE(opened.count(), 1);
    delete host;
    delete device;
}

void TestLoopbackTransport::write_arrivesAtPeer_everyByteValue()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    host->open(LineSettings{});
    QSignalSpy received(device, &Transport::dataReceived);
    QSignalSpy written(host, &Transport::bytesWritten);
    const QByteArray all = test::allByteValues();
    QCOMPARE(host->write(all), qint64(all.size()));
    QTRY_COMPARE(test::joinedBytes(received), all);
    QTRY_COMPARE(written.count(), 1);
    QCOMPARE(written.first().at(0).toLongLong(), qint64(all.size()));
    delete host;
    delete device;
}

void TestLoopbackTransport::write_bothDirections_inOrder()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    host->open(LineSettings{});
    device->open(LineSettings{});
    QSignalSpy atDevice(device, &Transport::dataReceived);
    QSignalSpy atHost(host, &Transport::dataReceived);
    for (char c : QByteArray("abcdef"))
        host->write(QByteArray(1, c));
    device->write(QByteArray("\x06\x15", 2));
    QTRY_COMPARE(test::joinedBytes(atDevice), QByteArray("abcdef"));
    QTRY_COMPARE(test::joinedBytes(atHost), QByteArray("\x06\x15", 2));
    delete host;
    delete device;
}

void TestLoopbackTransport::write_whenClosed_fails()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    QSignalSpy received(device, &Transport::dataReceived);
    QCOMPARE(host->write("x"), qint64(-1));
    QVERIFY(test::staysQuiet(received, 20));
    delete host;
    delete device;
}

void TestLoopbackTransport::discardOutput_dropsBytesInFlight()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    host->open(LineSettings{});
    QSignalSpy received(device, &Transport::dataReceived);
    host->write(QByteArray(1000, 'q')); // queued, not yet delivered
    host->discardOutput();
    host->write(QByteArray("\x13", 1)); // the stop byte must not wait behind the stream
    QTRY_COMPARE(test::joinedBytes(received), QByteArray("\x13", 1));
    QVERIFY(test::staysQuiet(received, 20));
    delete host;
    delete device;
}

void TestLoopbackTransport::simulateFailure_failedOnceThenClosed()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    host->open(LineSettings{});
    QSignalSpy failed(host, &Transport::failed);
    QSignalSpy closed(host, &Transport::closed);
    host->simulateFailure("peer vanished");
    host->simulateFailure("again");
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.first().at(0).toString(), QStringLiteral("peer vanished"));
    QCOMPARE(closed.count(), 1);
    QVERIFY(!host->isOpen());
    delete host;
    delete device;
}

void TestLoopbackTransport::close_emitsClosedOnce()
{
    auto [host, device] = LoopbackTransport::createPair(this);
    host->open(LineSettings{});
    QSignalSpy closed(host, &Transport::closed);
    host->close();
    host->close();
    QCOMPARE(closed.count(), 1);
    QVERIFY(!host->isOpen());
    delete host;
    delete device;
}

STEPDECK_TEST_GUILESS_MAIN(TestLoopbackTransport)
#include "tst_loopbacktransport.moc"
