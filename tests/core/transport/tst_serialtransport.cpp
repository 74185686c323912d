// SerialTransport over a real pseudo-terminal (PtyEndpoint is the device side), the way the
// end-to-end tests and stepdeck-sim use it. Line: E-LAB's 57600 8N2.
#include "TestMain.h"
#include "TestSupport.h"
#include "protocols/elab/ElabModel.h"
#include "sim/PtyEndpoint.h"
#include "transport/SerialTransport.h"
#include <QFileInfo>
#include <QtTest>
#include <memory>

using namespace stepdeck;

class TestSerialTransport : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void open_onPty_emitsOpened();
    void bytes_bothWays_everyValueIncludingXonXoff();
    void bytes_largeBlockFromDevice_arrivesComplete();
    void discardOutput_keepsPortUsable();
    void setResetLine_onPty_reportsCleanlyAndStaysOpen();
    void peerVanishes_failedExactlyOnce_portClosed_thenQuiet();
    void reopen_afterClose_works();
    void open_missingDevice_failsWithPath();
    void open_secondTimeSamePath_fails();

private:
    bool openHost(SerialTransport& host);

    std::unique_ptr<PtyEndpoint> m_device;
};

void TestSerialTransport::init()
{
    m_device = std::make_unique<PtyEndpoint>();
    QString error;
    QVERIFY2(m_device->create(&error), qPrintable(error));
    QVERIFY(QFileInfo::exists(m_device->slavePath()));
}

void TestSerialTransport::cleanup()
{
    m_device.reset();
}

bool TestSerialTransport::openHost(SerialTransport& host)
{
    QSignalSpy opened(&host, &Transport::opened);
    QSignalSpy failed(&host, &Transport::failed);
    host.open(elab::lineSettings());
    if (!opened.wait(2000)) {
        qWarning() << "open failed:" << failed;
        return false;
    }
    return host.isOpen();
}

void TestSerialTransport::open_onPty_emitsOpened()
{
    SerialTransport host(m_device->slavePath());
    QSignalSpy failed(&host, &Transport::failed);
    QVERIFY(openHost(host));
    QCOMPARE(host.description(), m_device->slavePath());
    QCOMPARE(failed.count(), 0); // RTS refusal on a pty is not an error
}

void TestSerialTransport::bytes_bothWays_everyValueIncludingXonXoff()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy atDevice(m_device.get(), &Transport::dataReceived);
    QSignalSpy atHost(&host, &Transport::dataReceived);

    // The control characters that software flow control or a cooked tty would eat first.
    const QByteArray critical("\x00\x11\x13\xFF\x0D\x0A\x12\x03", 8);
    QCOMPARE(host.write(critical), qint64(critical.size()));
    QTRY_COMPARE(test::joinedBytes(atDevice), critical);
    QCOMPARE(m_device->write(critical), qint64(critical.size()));
    QTRY_COMPARE(test::joinedBytes(atHost), critical);

    atDevice.clear();
    atHost.clear();
    const QByteArray all = test::allByteValues();
    host.write(all);
    m_device->write(all);
    QTRY_COMPARE(test::joinedBytes(atDevice), all);
    QTRY_COMPARE(test::joinedBytes(atHost), all);
}

void TestSerialTransport::bytes_largeBlockFromDevice_arrivesComplete()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy atHost(&host, &Transport::dataReceived);
    // Larger than the pty's buffer: the endpoint must queue and resume on writability.
    QByteArray block;
    for (int i = 0; i < 64 * 1024; ++i)
        block.append(char(i * 7));
    m_device->write(block);
    QTRY_COMPARE_WITH_TIMEOUT(test::joinedBytes(atHost).size(), block.size(), 10000);
    QCOMPARE(test::joinedBytes(atHost), block);
    QCOMPARE(m_device->bytesToWrite(), qint64(0));
}

void TestSerialTransport::discardOutput_keepsPortUsable()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy failed(&host, &Transport::failed);
    QSignalSpy atDevice(m_device.get(), &Transport::dataReceived);
    host.write(QByteArray(100, 'x'));
    host.discardOutput();
    QCOMPARE(host.bytesToWrite(), qint64(0));
    host.write(QByteArray("\x13", 1)); // ForceStopMove
    QTRY_VERIFY(test::joinedBytes(atDevice).endsWith('\x13'));
    QVERIFY(host.isOpen());
    QCOMPARE(failed.count(), 0);
}

void TestSerialTransport::setResetLine_onPty_reportsCleanlyAndStaysOpen()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy failed(&host, &Transport::failed);
    QSignalSpy closed(&host, &Transport::closed);
    QString error;
    // Ptys refuse the RTS ioctl (engineering notes); a real port would say true.
    QVERIFY(!host.setResetLine(true, &error));
    QVERIFY2(error.contains(m_device->slavePath()) && error.contains("RTS"), qPrintable(error));
    QVERIFY(host.isOpen());
    QVERIFY(test::staysQuiet(failed, 50));
    QCOMPARE(closed.count(), 0);

    // Still fully usable afterwards.
    QSignalSpy atDevice(m_device.get(), &Transport::dataReceived);
    host.write("ok");
    QTRY_COMPARE(test::joinedBytes(atDevice), QByteArray("ok"));
}

void TestSerialTransport::peerVanishes_failedExactlyOnce_portClosed_thenQuiet()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy failed(&host, &Transport::failed);
    QSignalSpy closed(&host, &Transport::closed);
    QSignalSpy received(&host, &Transport::dataReceived);
    host.write(QByteArray(50, 'm')); // mid-move: traffic in flight

    m_device->vanish();
    QVERIFY(failed.wait(2000));
    QCOMPARE(failed.count(), 1);
    const QString reason = failed.first().at(0).toString();
    QVERIFY2(reason.contains(m_device->slavePath()) && reason.contains("lost"), qPrintable(reason));
    QVERIFY(!host.isOpen());
    QTRY_COMPARE(closed.count(), 1);
    // Qt 6.4 would re-emit ReadError tens of thousands of times here if the port stayed
    // open; the transport must stay silent.
    QVERIFY(test::staysQuiet(failed, 200));
    QCOMPARE(failed.count(), 1);
    QCOMPARE(closed.count(), 1);
    QCOMPARE(received.count(), 0);
    QCOMPARE(host.write("x"), qint64(-1));
}

void TestSerialTransport::reopen_afterClose_works()
{
    SerialTransport host(m_device->slavePath());
    QVERIFY(openHost(host));
    QSignalSpy closed(&host, &Transport::closed);
    host.close();
    QCOMPARE(closed.count(), 1);
    QVERIFY(!host.isOpen());
    QVERIFY(openHost(host));
    QSignalSpy atDevice(m_device.get(), &Transport::dataReceived);
    host.write("again");
    QTRY_COMPARE(test::joinedBytes(atDevice), QByteArray("again"));
}

void TestSerialTransport::open_missingDevice_failsWithPath()
{
    SerialTransport host(QStringLiteral("/dev/stepdeck-no-such-port"));
    QSignalSpy opened(&host, &Transport::opened);
    QSignalSpy failed(&host, &Transport::failed);
    host.open(elab::lineSettings());
    QCOMPARE(failed.count(), 0); // reported through the event loop
    QVERIFY(failed.wait(2000));
    QCOMPARE(failed.count(), 1);
    QVERIFY2(failed.first().at(0).toString().contains("/dev/stepdeck-no-such-port"),
             qPrintable(failed.first().at(0).toString()));
    QCOMPARE(opened.count(), 0);
    QVERIFY(!host.isOpen());
}

void TestSerialTransport::open_secondTimeSamePath_fails()
{
    SerialTransport first(m_device->slavePath());
    QVERIFY(openHost(first));
    SerialTransport second(m_device->slavePath());
    QSignalSpy failed(&second, &Transport::failed);
    second.open(elab::lineSettings());
    QVERIFY(failed.wait(2000));
    QVERIFY2(failed.first().at(0).toString().contains("in use"),
             qPrintable(failed.first().at(0).toString()));
    QVERIFY(first.isOpen());
}

STEPDECK_TEST_GUILESS_MAIN(TestSerialTransport)
#include "tst_serialtransport.moc"
