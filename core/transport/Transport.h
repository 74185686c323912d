#pragma once
#include "model/LineSettings.h"
#include <QByteArray>
#include <QObject>

namespace stepdeck {

// A byte link to a controller (serial port, TCP device server, in-memory pair).
// Contract, for every implementation:
// - open() is asynchronous: exactly one of opened() or failed() follows.
// - On the first error of any kind the transport closes itself and emits failed() once
//   (Qt 6.4's QSerialPort otherwise spins on ReadError when the peer vanishes).
// - write() hands bytes over in order; discardOutput() drops what has not left yet, so a
//   panic byte written next is not stuck behind queued data.
// - A byte counts as sent only once it has left the process: write() merely queues it, and
//   close() throws away what is still queued. flushOutput() waits (bounded) until the queue
//   has been handed to the operating system; every stop written before a close goes through it.
class Transport : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    virtual void open(const LineSettings& settings) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual qint64 write(const QByteArray& bytes) = 0;
    virtual void discardOutput() = 0;
    virtual qint64 bytesToWrite() const = 0;
    // Hands what write() queued to the operating system now instead of in the event loop's
    // next pass, without blocking (what the driver does not take stays queued, in order).
    // For the bytes that overtake everything (stop, panic): on a loaded machine the next pass
    // can come a scheduler slice later (issue 21). Transports that hand bytes over at write()
    // need nothing here.
    virtual void pushOutput() {}
    // Blocks at most timeoutMs until everything written has left the process (serial: handed
    // to the kernel's tty queue). Returns true when nothing of ours is left in the process.
    // Only for the last bytes before a close: the caller's thread is blocked meanwhile.
    virtual bool flushOutput(int timeoutMs) = 0;
    // Bytes written and not yet on the wire as far as the driver tells: the process's own
    // queue plus, for a serial port, the kernel's output queue (TIOCOUTQ). Not the whole
    // truth: a pseudo-terminal reports no queue and a USB adapter's own FIFO is not counted,
    // so streams pace by wire time as well (WireBudget).
    virtual qint64 pendingOutputBytes() const { return bytesToWrite(); }
    // Drives the line some boards use as hardware reset (LineSettings::resetLine given to
    // open()). Returns false and says why where the link cannot (a pseudo-terminal, TCP, ...).
    virtual bool setResetLine(bool asserted, QString* error)
    {
        Q_UNUSED(asserted)
        if (error)
            *error = tr("this link has no modem control lines");
        return false;
    }
    virtual QString description() const = 0;

Q_SIGNALS:
    void opened();
    void failed(const QString& reason);
    void closed();
    void dataReceived(const QByteArray& bytes);
    void bytesWritten(qint64 count);
};

} // namespace stepdeck
