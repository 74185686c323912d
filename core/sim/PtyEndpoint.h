#pragma once
#include "transport/Transport.h"
#include <QTimer>

class QSocketNotifier;

namespace stepdeck {

// The DEVICE side of a pseudo-terminal: a simulator attaches to this end, the application
// opens slavePath() with QSerialPort exactly as it would open a USB adapter.
// Used by stepdeck-sim and by the end-to-end tests.
//
// The master fd is non-blocking; reads come through a QSocketNotifier, writes that would
// block wait in an own buffer behind a write notifier. The endpoint keeps its own descriptor
// of the slave open (see PtyEndpoint.cpp for why).
class PtyEndpoint : public Transport
{
    Q_OBJECT
public:
    explicit PtyEndpoint(QObject* parent = nullptr);
    ~PtyEndpoint() override;

    // Creates the pseudo-terminal now (raw mode). On failure returns false and says why.
    // slavePath() is valid afterwards; create() is implied by open().
    bool create(QString* error = nullptr);
    QString slavePath() const { return m_slavePath; }

    void open(const LineSettings& settings) override; // create() + opened()/failed() queued
    void close() override;                            // the device vanishes for the app
    bool isOpen() const override { return m_master >= 0; }
    qint64 write(const QByteArray& bytes) override;
    void discardOutput() override { m_out.clear(); }
    qint64 bytesToWrite() const override { return m_out.size(); }
    bool flushOutput(int timeoutMs) override;
    QString description() const override { return m_slavePath; }

    // Test hook, "peer vanishes mid-move": closes the pty as if the USB adapter had been
    // unplugged. The application's QSerialPort sees EIO/hang-up. Emits closed().
    void vanish() { close(); }

private:
    void onReadable();
    void onWritable();
    void flushOut();
    void pauseReading();
    void fail(const QString& reason);

    int m_master = -1;
    int m_slave = -1; // held open by us: keeps the master free of EIO while the app is away
    QString m_slavePath;
    QSocketNotifier* m_readNotifier = nullptr;
    QSocketNotifier* m_writeNotifier = nullptr;
    QTimer m_retryTimer{this}; // re-arms reading after EIO (no peer) without spinning
    QByteArray m_out;
    quint64 m_generation = 0;
};

} // namespace stepdeck
