#pragma once
#include <QMutex>
#include <QObject>
#include <QTimer>
#include <functional>

class QThread;

namespace stepdeck::ui {

struct PortEntry
{
    QString path;  // what the transport opens ("/dev/ttyUSB0")
    QString label; // "ttyUSB0 - FT232R USB UART (0403:6001)"
    // The USB identity, when the port is a USB device (issue 10: auto-reconnect follows the
    // same device by VID:PID + serial number, whatever path it comes back under).
    bool usb = false;
    quint16 vendorId = 0;
    quint16 productId = 0;
    QString serialNumber;
    bool operator==(const PortEntry& o) const
    {
        return path == o.path && label == o.label && usb == o.usb && vendorId == o.vendorId &&
               productId == o.productId && serialNumber == o.serialNumber;
    }
};

// Lists serial ports (core's listSerialPorts()) and rescans periodically, so ports that appear or
// vanish (USB adapters) show up without a restart. QSerialPortInfo does not list ptys: the
// connection bar accepts a typed path for those.
// The enumeration (udev/sysfs, can take tens of milliseconds) runs in a worker thread: the
// GUI never waits for it. ports() is empty until the first scan has come back.
class PortScanner : public QObject
{
    Q_OBJECT
public:
    using ScanFunction = std::function<QList<PortEntry>()>;

    // scan: how ports are listed (default: scan()); tests pass fake lists.
    explicit PortScanner(QObject* parent = nullptr, ScanFunction scan = {});
    ~PortScanner() override;

    const QList<PortEntry>& ports() const { return m_ports; }
    void setInterval(int ms) { m_timer.setInterval(ms); }
    void setScanFunction(ScanFunction scan);
    // Blocking enumeration (listSerialPorts()) as entries of the connection bar.
    static QList<PortEntry> scan();

public Q_SLOTS:
    // Starts an asynchronous scan (one at a time); scanned() follows.
    void rescan();

Q_SIGNALS:
    void portsChanged();
    // Every completed scan, changed or not.
    void scanned(const QList<stepdeck::ui::PortEntry>& ports);

private:
    void apply(const QList<PortEntry>& ports);

    QTimer m_timer;
    QList<PortEntry> m_ports;
    QThread* m_thread;
    QObject* m_worker;
    QMutex m_scanMutex;
    ScanFunction m_scan;
    bool m_busy = false;
    bool m_again = false;
};

} // namespace stepdeck::ui
