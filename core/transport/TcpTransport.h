#pragma once
#include "Transport.h"
#include <QTcpSocket>
#include <QTimer>

namespace stepdeck {

// Raw TCP to a serial device server ("tcp://HOST:PORT"); the server forwards bytes to the
// controller's serial line, so line settings are the server's business and ignored here.
//
// Limitation: QTcpSocket cannot take back bytes it has buffered, and the kernel cannot take
// back what it has sent. discardOutput() therefore only drops this transport's own queue:
// bytes are handed to the socket in small chunks (kSocketChunk) once the socket has drained,
// so at most one chunk can still be ahead of a panic byte.
class TcpTransport : public Transport
{
    Q_OBJECT
public:
    explicit TcpTransport(const QString& url, QObject* parent = nullptr);
    ~TcpTransport() override;

    // Parses "tcp://HOST:PORT"; on error returns false and says why.
    static bool parseUrl(const QString& url, QString* host, quint16* port, QString* error);

    void open(const LineSettings& settings) override;
    void close() override;
    bool isOpen() const override;
    qint64 write(const QByteArray& bytes) override;
    void discardOutput() override;
    qint64 bytesToWrite() const override;
    bool flushOutput(int timeoutMs) override;
    QString description() const override { return m_url; }

    void setConnectTimeout(int ms) { m_connectTimeoutMs = ms; }

    static constexpr qint64 kSocketChunk = 64;

private:
    void onConnected();
    void onReadyRead();
    void onBytesWritten(qint64 count);
    void onError(QAbstractSocket::SocketError error);
    void fail(const QString& reason);
    void pump();

    QString m_url;
    QTcpSocket m_socket;
    QTimer m_connectTimer;
    QByteArray m_pending; // written by the application, not yet handed to the socket
    int m_connectTimeoutMs = 5000;
    bool m_open = false;
    bool m_connecting = false;
    quint64 m_generation = 0;
};

} // namespace stepdeck
