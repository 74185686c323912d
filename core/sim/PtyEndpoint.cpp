#include "PtyEndpoint.h"
#include "Logging.h"
#include <QDeadlineTimer>
#include <QMetaObject>
#include <QSocketNotifier>
#include <QThread>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

namespace stepdeck {

// Why we hold our own slave descriptor: a pty master returns EIO from read() (and the read
// notifier fires continuously) whenever no process has the slave open -- before the
// application opens it, between a close and a reopen, and after it exits. Holding one slave
// fd ourselves keeps the line "up" for the master, so the notifier only fires on real data.
// The application's bytes are unaffected (we never read this fd). EIO is still handled
// defensively by pausing the notifier and polling every kRetryMs, never by spinning.
namespace {
constexpr int kRetryMs = 20;
constexpr int kReadChunk = 4096;

bool setNonBlockingCloexec(int fd)
{
    const int fl = ::fcntl(fd, F_GETFL);
    const int fdfl = ::fcntl(fd, F_GETFD);
    return fl >= 0 && fdfl >= 0 && ::fcntl(fd, F_SETFL, fl | O_NONBLOCK) == 0 &&
           ::fcntl(fd, F_SETFD, fdfl | FD_CLOEXEC) == 0;
}
} // namespace

PtyEndpoint::PtyEndpoint(QObject* parent) : Transport(parent)
{
    m_retryTimer.setSingleShot(true);
    m_retryTimer.setInterval(kRetryMs);
    connect(&m_retryTimer, &QTimer::timeout, this, [this] {
        if (m_readNotifier)
            m_readNotifier->setEnabled(true);
    });
}

PtyEndpoint::~PtyEndpoint()
{
    QSignalBlocker block(this);
    close();
}

bool PtyEndpoint::create(QString* error)
{
    if (m_master >= 0)
        return true;
    int master = -1, slave = -1;
    char name[256] = {};
    if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) {
        if (error)
            *error = tr("cannot create a pseudo-terminal: %1")
                         .arg(QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    // Raw on the slave side: no echo, no line editing, no CR/LF mapping, no XON/XOFF --
    // every byte value (0x00, 0x11, 0x13, 0xFF) passes unchanged until the app sets its own.
    termios tio{};
    if (::tcgetattr(slave, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::cfsetspeed(&tio, B57600);
        ::tcsetattr(slave, TCSANOW, &tio);
    }
    if (!setNonBlockingCloexec(master) || ::fcntl(slave, F_SETFD, FD_CLOEXEC) != 0) {
        if (error)
            *error = tr("cannot configure the pseudo-terminal: %1")
                         .arg(QString::fromLocal8Bit(std::strerror(errno)));
        ::close(master);
        ::close(slave);
        return false;
    }
    m_master = master;
    m_slave = slave;
    m_slavePath = QString::fromLocal8Bit(name);
    m_out.clear();
    m_readNotifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PtyEndpoint::onReadable);
    m_writeNotifier = new QSocketNotifier(m_master, QSocketNotifier::Write, this);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier, &QSocketNotifier::activated, this, &PtyEndpoint::onWritable);
    qCInfo(lcSimulator) << "pseudo-terminal" << m_slavePath;
    return true;
}

void PtyEndpoint::open(const LineSettings&)
{
    QString error;
    const bool ok = create(&error);
    const quint64 gen = ++m_generation;
    QMetaObject::invokeMethod(
        this,
        [this, gen, ok, error] {
            if (gen != m_generation)
                return;
            if (ok)
                Q_EMIT opened();
            else
                Q_EMIT failed(error);
        },
        Qt::QueuedConnection);
}

void PtyEndpoint::close()
{
    ++m_generation;
    if (m_master < 0)
        return;
    m_retryTimer.stop();
    // Notifiers stop before their descriptor is closed; deleteLater because close() may run
    // inside one of their own activated() signals.
    for (QSocketNotifier* n : {m_readNotifier, m_writeNotifier}) {
        n->setEnabled(false);
        n->deleteLater();
    }
    m_readNotifier = m_writeNotifier = nullptr;
    ::close(m_slave);
    ::close(m_master);
    m_slave = m_master = -1;
    m_out.clear();
    qCInfo(lcSimulator) << "pseudo-terminal closed" << m_slavePath;
    Q_EMIT closed();
}

qint64 PtyEndpoint::write(const QByteArray& bytes)
{
    if (m_master < 0)
        return -1;
    m_out += bytes;
    flushOut();
    return bytes.size();
}

void PtyEndpoint::flushOut()
{
    qint64 total = 0;
    while (!m_out.isEmpty() && m_master >= 0) {
        const ssize_t n = ::write(m_master, m_out.constData(), size_t(m_out.size()));
        if (n > 0) {
            m_out.remove(0, qsizetype(n));
            total += n;
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EIO) {
            fail(tr("pseudo-terminal %1: write failed: %2")
                     .arg(m_slavePath, QString::fromLocal8Bit(std::strerror(errno))));
            return;
        }
        // Full (or nobody reading yet): wait until the master is writable again.
        break;
    }
    if (m_writeNotifier)
        m_writeNotifier->setEnabled(!m_out.isEmpty());
    if (total > 0)
        Q_EMIT bytesWritten(total);
}

bool PtyEndpoint::flushOutput(int timeoutMs)
{
    // The device side rarely needs this (stepdeck-sim's last words); a bounded retry loop.
    QDeadlineTimer deadline(qMax(0, timeoutMs));
    flushOut();
    while (!m_out.isEmpty() && m_master >= 0 && !deadline.hasExpired()) {
        QThread::usleep(500);
        flushOut();
    }
    return m_master >= 0 && m_out.isEmpty();
}

void PtyEndpoint::onWritable()
{
    flushOut();
}

void PtyEndpoint::onReadable()
{
    if (m_master < 0)
        return;
    char buf[kReadChunk];
    const ssize_t n = ::read(m_master, buf, sizeof buf);
    if (n > 0) {
        Q_EMIT dataReceived(QByteArray(buf, int(n)));
        return;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR))
        return;
    if (n == 0 || errno == EIO) {
        pauseReading(); // no application on the slave right now
        return;
    }
    fail(tr("pseudo-terminal %1: read failed: %2")
             .arg(m_slavePath, QString::fromLocal8Bit(std::strerror(errno))));
}

void PtyEndpoint::pauseReading()
{
    if (m_readNotifier)
        m_readNotifier->setEnabled(false);
    m_retryTimer.start();
}

void PtyEndpoint::fail(const QString& reason)
{
    qCWarning(lcSimulator) << reason;
    {
        QSignalBlocker block(this); // closed() follows failed(), not before it
        close();
    }
    Q_EMIT failed(reason);
    Q_EMIT closed();
}

} // namespace stepdeck
