// TcpTransport against a local QTcpServer standing in for a serial device server.
#include "TestMain.h"
#include "TestSupport.h"
#include "transport/TcpTransport.h"
#include <QTcpServer>
#include <QTcpSocket>
#include <QtTest>

using namespace stepdeck;

class TestTcpTransport : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void parseUrl_valid_data();
    void parseUrl_valid();
    void open_badUrl_failsWithReason_data();
    void open_badUrl_failsWithReason();
    void open_connects_bytesBothWays();
    void open_refused_failsOnce();
    void serverCloses_failedExactlyOnce_thenQuiet();
    void discardOutput_dropsQueuedBytes();

private:
    QString url() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(m_server->serverPort()); }
    // Opens `host` against m_server; returns the server-side socket.
    QTcpSocket* connectHost(TcpTransport& host);

    QTcpServer* m_server = nullptr;
};

void TestTcpTransport::init()
{
    m_server = new QTcpServer(this);
    QVERIFY(m_server->listen(QHostAddress::LocalHost, 0));
}

void TestTcpTransport::cleanup()
{
    delete m_server;
    m_server = nullptr;
}

QTcpSocket* TestTcpTransport::connectHost(TcpTransport& host)
{
    QSignalSpy opened(&host, &Transport::opened);
    host.open(LineSettings{});
    if (!opened.wait(3000))
        return nullptr;
    // The accept usually happened while waiting for opened().
    if (!m_server->hasPendingConnections() && !m_server->waitForNewConnection(3000))
        return nullptr;
    return m_server->nextPendingConnection();
}

void TestTcpTransport::parseUrl_valid_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::newRow("ipv4") << "tcp://192.168.1.20:4001"
                          << "192.168.1.20" << 4001;
    QTest::newRow("name") << "tcp://moxa.local:950"
                          << "moxa.local" << 950;
    QTest::newRow("ipv6") << "tcp://[::1]:23"
                          << "::1" << 23;
    QTest::newRow("trailing slash") << "tcp://h:65535/"
                                    << "h" << 65535;
}

void TestTcpTransport::parseUrl_valid()
{
    QFETCH(QString, url);
    QFETCH(QString, host);
    QFETCH(int, port);
    QString h, error;
    quint16 p = 0;
    QVERIFY2(TcpTransport::parseUrl(url, &h, &p, &error), qPrintable(error));
    QCOMPARE(h, host);
    QCOMPARE(int(p), port);
}

void TestTcpTransport::open_badUrl_failsWithReason_data()
{
    QTest::addColumn<QString>("url");
    QTest::newRow("no host, no port") << "tcp://";
    QTest::newRow("no port") << "tcp://host";
    QTest::newRow("port 0") << "tcp://host:0";
    QTest::newRow("port too big") << "tcp://host:99999";
    QTest::newRow("port not a number") << "tcp://host:abc";
    QTest::newRow("path") << "tcp://host:12/dev/ttyS0";
    QTest::newRow("other scheme") << "udp://host:12";
    QTest::newRow("query") << "tcp://host:12?baud=9600";
}

void TestTcpTransport::open_badUrl_failsWithReason()
{
    QFETCH(QString, url);
    TcpTransport host(url);
    QSignalSpy opened(&host, &Transport::opened);
    QSignalSpy failed(&host, &Transport::failed);
    host.open(LineSettings{});
    QVERIFY(failed.wait(1000));
    QCOMPARE(failed.count(), 1);
    const QString reason = failed.first().at(0).toString();
    QVERIFY2(reason.contains("tcp://HOST:PORT"), qPrintable(reason));
    QCOMPARE(opened.count(), 0);
    QVERIFY(!host.isOpen());
}

void TestTcpTransport::open_connects_bytesBothWays()
{
    TcpTransport host(url());
    QTcpSocket* peer = connectHost(host);
    QVERIFY(peer);
    QVERIFY(host.isOpen());
    QCOMPARE(host.description(), url());

    QSignalSpy atHost(&host, &Transport::dataReceived);
    const QByteArray all = test::allByteValues();
    QCOMPARE(host.write(all), qint64(all.size()));
    QByteArray atPeer;
    QTRY_VERIFY((atPeer += peer->readAll()).size() == all.size());
    QCOMPARE(atPeer, all);
    peer->write(all);
    QTRY_COMPARE(test::joinedBytes(atHost), all);
}

void TestTcpTransport::open_refused_failsOnce()
{
    const QString closedUrl = url();
    m_server->close(); // nothing listens on that port any more
    TcpTransport host(closedUrl);
    QSignalSpy failed(&host, &Transport::failed);
    host.open(LineSettings{});
    QVERIFY(failed.wait(5000));
    QVERIFY2(failed.first().at(0).toString().contains(closedUrl),
             qPrintable(failed.first().at(0).toString()));
    QVERIFY(test::staysQuiet(failed, 100));
    QVERIFY(!host.isOpen());
}

void TestTcpTransport::serverCloses_failedExactlyOnce_thenQuiet()
{
    TcpTransport host(url());
    QTcpSocket* peer = connectHost(host);
    QVERIFY(peer);
    QSignalSpy failed(&host, &Transport::failed);
    QSignalSpy closed(&host, &Transport::closed);
    peer->close();
    QVERIFY(failed.wait(3000));
    QVERIFY2(failed.first().at(0).toString().contains("closed the connection"),
             qPrintable(failed.first().at(0).toString()));
    QVERIFY(!host.isOpen());
    QTRY_COMPARE(closed.count(), 1);
    QVERIFY(test::staysQuiet(failed, 200));
    QCOMPARE(failed.count(), 1);
    QCOMPARE(host.write("x"), qint64(-1));
}

void TestTcpTransport::discardOutput_dropsQueuedBytes()
{
    TcpTransport host(url());
    QTcpSocket* peer = connectHost(host);
    QVERIFY(peer);
    host.write(QByteArray(10000, 'q'));
    // Only the chunk already inside the socket can still leave.
    host.discardOutput();
    QVERIFY(host.bytesToWrite() <= TcpTransport::kSocketChunk);
    host.write(QByteArray("\x13", 1));
    QByteArray atPeer;
    QTRY_VERIFY((atPeer += peer->readAll()).endsWith('\x13'));
    QVERIFY2(atPeer.size() <= TcpTransport::kSocketChunk + 1,
             qPrintable(QString::number(atPeer.size())));
}

STEPDECK_TEST_GUILESS_MAIN(TestTcpTransport)
#include "tst_tcptransport.moc"
