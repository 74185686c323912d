#pragma once
#include "Transport.h"
#include <QSerialPort>

namespace stepdeck {

// A local serial port (USB adapter, on-board UART or a pseudo-terminal).
// - Never any flow control: E-LAB's RTS is the board's reset line and the host itself sends
//   0x13 (ForceStopMove), which software flow control would swallow.
// - Both modem lines (RTS, DTR) are held low on open where the port supports it (ptys do not;
//   that is not an error): one of them is the board's reset line (LineSettings::resetLine).
// - The first error of any kind closes the port and is reported once: Qt 6.4 otherwise
//   re-emits ReadError tens of thousands of times per 100 ms when the device vanishes.
class SerialTransport : public Transport
{
    Q_OBJECT
public:
    explicit SerialTransport(const QString& portName, QObject* parent = nullptr);
    ~SerialTransport() override;

    void open(const LineSettings& settings) override;
    void close() override;
    bool isOpen() const override;
    qint64 write(const QByteArray& bytes) override;
    void discardOutput() override;
    void pushOutput() override;
    qint64 bytesToWrite() const override;
    bool flushOutput(int timeoutMs) override;
    qint64 pendingOutputBytes() const override;
    bool setResetLine(bool asserted, QString* error) override;
    QString description() const override;

    QString portName() const { return m_portName; }

private:
    void onReadyRead();
    void onError(QSerialPort::SerialPortError error);
    void shutDown(const QString& reason);
    QString reasonFor(QSerialPort::SerialPortError error) const;
    bool applySettings(const LineSettings& settings, QString* error);

    bool driveLine(LineSettings::ResetLine line, bool asserted, QString* error);

    QString m_portName;
    QSerialPort m_port;
    LineSettings::ResetLine m_resetLine = LineSettings::ResetLine::Rts;
    bool m_failed = false;        // first error seen; the port is closing
    bool m_expectErrors = false;  // inside a call whose failure we handle from its result
    quint64 m_openGeneration = 0; // stale queued open/shut-down calls are ignored
};

} // namespace stepdeck
