#pragma once
#include <QObject>
#include <QTimer>

namespace stepdeck::ui {

struct PortEntry
{
    QString path;  // what the transport opens ("/dev/ttyUSB0")
    QString label; // "ttyUSB0 - FT232R USB UART (0403:6001)"
    bool operator==(const PortEntry& o) const { return path == o.path && label == o.label; }
};

// Lists serial ports with QSerialPortInfo and rescans periodically, so ports that appear or
// vanish (USB adapters) show up without a restart. QSerialPortInfo does not list ptys: the
// connection bar accepts a typed path for those.
class PortScanner : public QObject
{
    Q_OBJECT
public:
    explicit PortScanner(QObject* parent = nullptr);

    const QList<PortEntry>& ports() const { return m_ports; }
    void setInterval(int ms) { m_timer.setInterval(ms); }
    static QList<PortEntry> scan();

public Q_SLOTS:
    void rescan();

Q_SIGNALS:
    void portsChanged();

private:
    QTimer m_timer;
    QList<PortEntry> m_ports;
};

} // namespace stepdeck::ui
