#include "SerialTransport.h"
#include "Logging.h"
#include "SerialPortAccess.h"
#include <QDeadlineTimer>
#include <QMetaObject>
#include <sys/ioctl.h>
#include <termios.h>

namespace stepdeck {

SerialTransport::SerialTransport(const QString& portName, QObject* parent)
    : Transport(parent), m_portName(portName), m_port(this)
{
    connect(&m_port, &QSerialPort::readyRead, this, &SerialTransport::onReadyRead);
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
    connect(&m_port, &QSerialPort::bytesWritten, this, &Transport::bytesWritten);
}

SerialTransport::~SerialTransport()
{
    // Quietly: nobody listens to a transport being destroyed.
    QSignalBlocker block(this);
    if (m_port.isOpen())
        m_port.close();
}

QString SerialTransport::description() const
{
    return m_portName;
}

bool SerialTransport::applySettings(const LineSettings& s, QString* error)
{
    QSerialPort::StopBits stop = s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    if (s.parity == LineSettings::Parity::Even)
        parity = QSerialPort::EvenParity;
    else if (s.parity == LineSettings::Parity::Odd)
        parity = QSerialPort::OddParity;
    const bool ok = m_port.setBaudRate(s.baudRate) &&
                    m_port.setDataBits(QSerialPort::DataBits(s.dataBits)) &&
                    m_port.setParity(parity) && m_port.setStopBits(stop) &&
                    m_port.setFlowControl(QSerialPort::NoFlowControl);
    if (!ok && error) {
        *error = tr("serial port %1 does not support %2 baud, %3%4%5")
                     .arg(m_portName)
                     .arg(s.baudRate)
                     .arg(s.dataBits)
                     .arg(parity == QSerialPort::NoParity     ? QLatin1Char('N')
                          : parity == QSerialPort::EvenParity ? QLatin1Char('E')
                                                              : QLatin1Char('O'))
                     .arg(s.stopBits);
    }
    return ok;
}

void SerialTransport::open(const LineSettings& settings)
{
    if (m_port.isOpen())
        close();
    m_failed = false;
    const quint64 gen = ++m_openGeneration;
    m_resetLine = settings.resetLine;
    m_port.setPortName(m_portName);
    // Settings given before open() take effect with the open itself (no moment at Qt's
    // default 9600 8N1); afterwards they are set once more so that a setting the port refuses
    // is reported by name rather than lost.
    QString reason;
    m_expectErrors = true;
    applySettings(settings, nullptr);
    bool ok = !m_portName.isEmpty() && m_port.open(QIODevice::ReadWrite);
    if (m_portName.isEmpty())
        reason = tr("no serial port given");
    else if (!ok)
        reason = reasonFor(m_port.error());
    else if (!applySettings(settings, &reason))
        ok = false;
    m_expectErrors = false;
    if (!ok) {
        if (m_port.isOpen())
            m_port.close();
        m_port.clearError();
        m_failed = true;
        qCWarning(lcTransport) << "open failed:" << reason;
        QMetaObject::invokeMethod(
            this,
            [this, gen, reason] {
                if (gen == m_openGeneration)
                    Q_EMIT failed(reason);
            },
            Qt::QueuedConnection);
        return;
    }
    // Hold both modem lines low: one of them is the board's reset line, and the other one must
    // not be left asserted either (the E-LAB manual names RTS, its pin table DTR).
    // Pseudo-terminals refuse the ioctl ("Inappropriate ioctl"), which is expected there.
    for (const auto line : {LineSettings::ResetLine::Rts, LineSettings::ResetLine::Dtr}) {
        QString lineError;
        if (!driveLine(line, false, &lineError))
            qCDebug(lcTransport) << "modem line not controllable:" << lineError;
    }
    qCInfo(lcTransport) << "opened" << m_portName << settings.baudRate;
    QMetaObject::invokeMethod(
        this,
        [this, gen] {
            if (gen == m_openGeneration && m_port.isOpen() && !m_failed)
                Q_EMIT opened();
        },
        Qt::QueuedConnection);
}

void SerialTransport::close()
{
    ++m_openGeneration; // cancels queued opened()/failed()
    const bool wasOpen = m_port.isOpen() && !m_failed;
    m_failed = false;
    if (m_port.isOpen())
        m_port.close();
    m_port.clearError();
    if (wasOpen)
        Q_EMIT closed();
}

bool SerialTransport::isOpen() const
{
    return m_port.isOpen() && !m_failed;
}

qint64 SerialTransport::write(const QByteArray& bytes)
{
    if (!isOpen())
        return -1;
    return m_port.write(bytes);
}

void SerialTransport::discardOutput()
{
    if (!isOpen())
        return;
    // Drops QSerialPort's buffer and the driver's output queue (tcflush), so a panic byte
    // written next is not stuck behind a queued stream.
    m_expectErrors = true;
    m_port.clear(QSerialPort::Output);
    m_expectErrors = false;
}

void SerialTransport::pushOutput()
{
    // QSerialPort::write() only appends to its buffer and writes from the write notifier on
    // the next event-loop pass; flush() writes now with the port's non-blocking write(2) and
    // leaves the rest to the notifier (Qt 6.4 QSerialPortPrivate::flush on Unix). A failed
    // write is reported through errorOccurred as for any other write.
    if (isOpen())
        m_port.flush();
}

qint64 SerialTransport::bytesToWrite() const
{
    return isOpen() ? m_port.bytesToWrite() : 0;
}

bool SerialTransport::flushOutput(int timeoutMs)
{
    if (!isOpen())
        return false;
    // QSerialPort::close() drops its write buffer: wait until the kernel has taken all of it.
    const QDeadlineTimer deadline(qMax(0, timeoutMs));
    m_expectErrors = true;
    while (m_port.bytesToWrite() > 0 && !deadline.hasExpired()) {
        if (!m_port.waitForBytesWritten(int(qMax<qint64>(1, deadline.remainingTime()))))
            break;
    }
    m_expectErrors = false;
    const bool left = m_port.isOpen() && m_port.bytesToWrite() == 0;
    if (!left)
        qCWarning(lcTransport) << "flush: bytes still queued after" << timeoutMs << "ms";
    return left;
}

qint64 SerialTransport::pendingOutputBytes() const
{
    if (!isOpen())
        return 0;
    qint64 pending = m_port.bytesToWrite();
    int kernelQueue = 0;
    // TIOCOUTQ: bytes in the tty/USB-serial driver not yet on the wire (0 where unsupported).
    if (m_port.handle() >= 0 && ::ioctl(m_port.handle(), TIOCOUTQ, &kernelQueue) == 0)
        pending += qMax(0, kernelQueue);
    return pending;
}

bool SerialTransport::setResetLine(bool asserted, QString* error)
{
    return driveLine(m_resetLine, asserted, error);
}

bool SerialTransport::driveLine(LineSettings::ResetLine line, bool asserted, QString* error)
{
    const QString name =
        line == LineSettings::ResetLine::Dtr ? QStringLiteral("DTR") : QStringLiteral("RTS");
    if (!isOpen()) {
        if (error)
            *error = tr("serial port %1 is not open").arg(m_portName);
        return false;
    }
    // A refused ioctl (pseudo-terminal, some USB adapters) is an answer, not a broken link:
    // report it through the return value and keep the port open.
    m_expectErrors = true;
    const bool ok = line == LineSettings::ResetLine::Dtr ? m_port.setDataTerminalReady(asserted)
                                                         : m_port.setRequestToSend(asserted);
    m_expectErrors = false;
    if (!ok) {
        if (error)
            *error = tr("serial port %1 cannot drive %2: %3")
                         .arg(m_portName, name, m_port.errorString());
        m_port.clearError();
    }
    return ok;
}

void SerialTransport::onReadyRead()
{
    if (m_failed)
        return;
    const QByteArray bytes = m_port.readAll();
    if (!bytes.isEmpty())
        Q_EMIT dataReceived(bytes);
}

void SerialTransport::onError(QSerialPort::SerialPortError error)
{
    if (error == QSerialPort::NoError || m_expectErrors || m_failed || !m_port.isOpen())
        return;
    m_failed = true; // isOpen() is false from here on; later errors are ignored
    const QString reason = reasonFor(error);
    qCWarning(lcTransport) << "serial error" << error << m_port.errorString() << "->" << reason;
    // Close outside QSerialPort's own notifier callback (it is still on the stack), but
    // before the event loop can spin on the dead descriptor again.
    const quint64 gen = m_openGeneration;
    QMetaObject::invokeMethod(
        this,
        [this, gen, reason] {
            if (gen == m_openGeneration)
                shutDown(reason);
        },
        Qt::QueuedConnection);
}

void SerialTransport::shutDown(const QString& reason)
{
    ++m_openGeneration;
    if (m_port.isOpen())
        m_port.close();
    m_port.clearError();
    Q_EMIT failed(reason);
    Q_EMIT closed();
}

QString SerialTransport::reasonFor(QSerialPort::SerialPortError error) const
{
    switch (error) {
    case QSerialPort::DeviceNotFoundError:
        return tr("no such port: %1").arg(m_portName);
    case QSerialPort::PermissionError:
        // Access denied (names the group to join) or locked by another program.
        return SerialPortAccess::probe(m_portName).deniedText();
    case QSerialPort::OpenError:
        return tr("serial port %1 is already open").arg(m_portName);
    case QSerialPort::ReadError:
    case QSerialPort::ResourceError:
        return tr("serial port %1 lost: the device vanished").arg(m_portName);
    case QSerialPort::WriteError:
        return tr("serial port %1 lost: writing to it failed").arg(m_portName);
    case QSerialPort::UnsupportedOperationError:
        return tr("serial port %1 refused an operation: %2").arg(m_portName, m_port.errorString());
    default:
        return tr("serial port %1 failed: %2").arg(m_portName, m_port.errorString());
    }
}

} // namespace stepdeck
