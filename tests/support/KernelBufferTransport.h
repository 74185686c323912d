#pragma once
// A host end that behaves like a serial port with a kernel tty buffer: write() takes
// everything at once and reports it written (as QSerialPort's bytesWritten does once write(2)
// succeeded), but the bytes reach the peer only at the line's character rate. A pty never
// shows this backlog, so tests of wire pacing use this instead.
// reportsQueue=false: the buffer is a USB adapter's own FIFO, which the driver does not count
// (pendingOutputBytes() stays 0 as TIOCOUTQ would): only the host's wire budget holds it back.
#include "model/LineSettings.h"
#include "transport/LoopbackTransport.h"
#include <QElapsedTimer>
#include <QTimer>

namespace stepdeck::testing {

class KernelBufferTransport : public LoopbackTransport
{
public:
    explicit KernelBufferTransport(const LineSettings& line, bool reportsQueue = true,
                                   QObject* parent = nullptr)
        : LoopbackTransport(parent), m_characterTimeUs(line.characterTimeUs()),
          m_reportsQueue(reportsQueue)
    {
        m_release.setTimerType(Qt::PreciseTimer);
        m_release.setInterval(1);
        connect(&m_release, &QTimer::timeout, this, &KernelBufferTransport::release);
        m_clock.start();
    }

    qint64 write(const QByteArray& bytes) override
    {
        if (!isOpen())
            return -1;
        if (m_kernel.isEmpty())
            m_lastReleaseUs = m_clock.nsecsElapsed() / 1000;
        m_kernel += bytes;
        m_maxQueued = qMax(m_maxQueued, qint64(m_kernel.size()));
        if (!m_release.isActive())
            m_release.start();
        QMetaObject::invokeMethod(
            this, [this, n = bytes.size()] { Q_EMIT bytesWritten(n); }, Qt::QueuedConnection);
        return bytes.size();
    }
    void discardOutput() override { m_kernel.clear(); } // tcflush(TCOFLUSH)
    qint64 pendingOutputBytes() const override { return m_reportsQueue ? m_kernel.size() : 0; }
    qint64 maxQueued() const { return m_maxQueued; } // the deepest the kernel queue got

private:
    void release()
    {
        const qint64 now = m_clock.nsecsElapsed() / 1000;
        const qint64 due = qint64((now - m_lastReleaseUs) / m_characterTimeUs);
        if (due <= 0)
            return;
        const QByteArray out = m_kernel.left(int(qMin<qint64>(due, m_kernel.size())));
        m_kernel.remove(0, out.size());
        m_lastReleaseUs += qint64(out.size() * m_characterTimeUs);
        if (LoopbackTransport* device = peer())
            Q_EMIT device->dataReceived(out); // on the wire now
        if (m_kernel.isEmpty())
            m_release.stop();
    }

    double m_characterTimeUs;
    bool m_reportsQueue;
    QByteArray m_kernel;
    QTimer m_release{this};
    QElapsedTimer m_clock;
    qint64 m_lastReleaseUs = 0;
    qint64 m_maxQueued = 0;
};

} // namespace stepdeck::testing
