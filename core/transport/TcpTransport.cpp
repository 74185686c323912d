#include "TcpTransport.h"
#include "Logging.h"
#include <QDeadlineTimer>
#include <QMetaObject>
#include <QUrl>

namespace stepdeck {

TcpTransport::TcpTransport(const QString& url, QObject* parent)
    : Transport(parent), m_url(url), m_socket(this), m_connectTimer(this)
{
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        fail(tr("%1: no connection within %2 ms").arg(m_url).arg(m_connectTimeoutMs));
    });
    connect(&m_socket, &QTcpSocket::connected, this, &TcpTransport::onConnected);
    connect(&m_socket, &QTcpSocket::readyRead, this, &TcpTransport::onReadyRead);
    connect(&m_socket, &QTcpSocket::bytesWritten, this, &TcpTransport::onBytesWritten);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &TcpTransport::onError);
}

TcpTransport::~TcpTransport()
{
    QSignalBlocker block(this);
    m_socket.abort();
}

bool TcpTransport::parseUrl(const QString& url, QString* host, quint16* port, QString* error)
{
    const QUrl u(url, QUrl::StrictMode);
    QString why;
    if (!u.isValid() || u.scheme() != QLatin1String("tcp"))
        why = tr("\"%1\" is not a TCP address; expected tcp://HOST:PORT").arg(url);
    else if (u.host().isEmpty())
        why = tr("\"%1\" names no host; expected tcp://HOST:PORT").arg(url);
    else if (u.port() < 1 || u.port() > 65535)
        why = tr("\"%1\" needs a port between 1 and 65535; expected tcp://HOST:PORT").arg(url);
    else if (!u.path().isEmpty() && u.path() != QLatin1String("/"))
        why = tr("\"%1\" has a path; expected tcp://HOST:PORT").arg(url);
    else if (u.hasQuery() || u.hasFragment() || !u.userInfo().isEmpty())
        why = tr("\"%1\" has extra parts; expected tcp://HOST:PORT").arg(url);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return false;
    }
    if (host)
        *host = u.host();
    if (port)
        *port = quint16(u.port());
    return true;
}

void TcpTransport::open(const LineSettings&)
{
    if (m_open || m_connecting)
        close();
    const quint64 gen = ++m_generation;
    QString host, error;
    quint16 port = 0;
    if (!parseUrl(m_url, &host, &port, &error)) {
        qCWarning(lcTransport) << error;
        QMetaObject::invokeMethod(
            this,
            [this, gen, error] {
                if (gen == m_generation)
                    Q_EMIT failed(error);
            },
            Qt::QueuedConnection);
        return;
    }
    m_connecting = true;
    m_pending.clear();
    m_connectTimer.start(m_connectTimeoutMs);
    // Asynchronous: connected() or errorOccurred() follows from the event loop.
    m_socket.connectToHost(host, port);
}

void TcpTransport::close()
{
    ++m_generation;
    const bool wasOpen = m_open;
    m_open = false;
    m_connecting = false;
    m_connectTimer.stop();
    m_pending.clear();
    {
        QSignalBlocker block(&m_socket);
        m_socket.abort();
    }
    if (wasOpen)
        Q_EMIT closed();
}

bool TcpTransport::isOpen() const
{
    return m_open;
}

qint64 TcpTransport::write(const QByteArray& bytes)
{
    if (!m_open)
        return -1;
    m_pending += bytes;
    pump();
    return bytes.size();
}

void TcpTransport::discardOutput()
{
    // Best effort, see the class comment: what the socket already holds still goes out.
    m_pending.clear();
}

qint64 TcpTransport::bytesToWrite() const
{
    return m_open ? m_pending.size() + m_socket.bytesToWrite() : 0;
}

bool TcpTransport::flushOutput(int timeoutMs)
{
    if (!m_open)
        return false;
    // The small-chunk queue first, then the socket's own buffer, all within one deadline.
    const QDeadlineTimer deadline(qMax(0, timeoutMs));
    while (m_open && bytesToWrite() > 0 && !deadline.hasExpired()) {
        if (m_socket.bytesToWrite() == 0)
            pump();
        if (!m_socket.waitForBytesWritten(int(qMax<qint64>(1, deadline.remainingTime()))))
            break;
    }
    return m_open && bytesToWrite() == 0;
}

void TcpTransport::pump()
{
    if (!m_open || m_pending.isEmpty() || m_socket.bytesToWrite() > 0)
        return;
    const QByteArray chunk = m_pending.left(kSocketChunk);
    m_pending.remove(0, chunk.size());
    m_socket.write(chunk);
}

void TcpTransport::onConnected()
{
    m_connectTimer.stop();
    m_connecting = false;
    m_open = true;
    // Small frames must not wait for Nagle's algorithm.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    qCInfo(lcTransport) << "connected" << m_url;
    Q_EMIT opened();
}

void TcpTransport::onReadyRead()
{
    if (!m_open)
        return;
    const QByteArray bytes = m_socket.readAll();
    if (!bytes.isEmpty())
        Q_EMIT dataReceived(bytes);
}

void TcpTransport::onBytesWritten(qint64 count)
{
    Q_EMIT bytesWritten(count);
    pump();
}

void TcpTransport::onError(QAbstractSocket::SocketError error)
{
    if (!m_open && !m_connecting)
        return;
    QString reason;
    switch (error) {
    case QAbstractSocket::RemoteHostClosedError:
        reason = tr("%1 lost: the device server closed the connection").arg(m_url);
        break;
    case QAbstractSocket::ConnectionRefusedError:
        reason = tr("%1: connection refused").arg(m_url);
        break;
    case QAbstractSocket::HostNotFoundError:
        reason = tr("%1: host not found").arg(m_url);
        break;
    default:
        reason = (m_open ? tr("%1 lost: %2") : tr("%1: cannot connect: %2"))
                     .arg(m_url, m_socket.errorString());
        break;
    }
    fail(reason);
}

void TcpTransport::fail(const QString& reason)
{
    if (!m_open && !m_connecting)
        return;
    const bool wasOpen = m_open;
    m_open = false;
    m_connecting = false;
    m_connectTimer.stop();
    m_pending.clear();
    const quint64 gen = ++m_generation;
    qCWarning(lcTransport) << reason;
    // Abort and report outside QTcpSocket's own callback.
    QMetaObject::invokeMethod(
        this,
        [this, gen, reason, wasOpen] {
            if (gen != m_generation)
                return;
            {
                QSignalBlocker block(&m_socket);
                m_socket.abort();
            }
            Q_EMIT failed(reason);
            if (wasOpen)
                Q_EMIT closed();
        },
        Qt::QueuedConnection);
}

} // namespace stepdeck
