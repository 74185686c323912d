#include "PortScanner.h"
#include <QSerialPortInfo>

namespace stepdeck::ui {

PortScanner::PortScanner(QObject* parent) : QObject(parent)
{
    m_timer.setInterval(2000);
    connect(&m_timer, &QTimer::timeout, this, &PortScanner::rescan);
    m_timer.start();
    m_ports = scan();
}

QList<PortEntry> PortScanner::scan()
{
    QList<PortEntry> list;
    const auto infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo& info : infos) {
        QString label = info.portName();
        if (!info.description().isEmpty())
            label += QStringLiteral(" \u2013 ") + info.description();
        if (info.hasVendorIdentifier() && info.hasProductIdentifier()) {
            label += QStringLiteral(" (%1:%2)")
                         .arg(info.vendorIdentifier(), 4, 16, QLatin1Char('0'))
                         .arg(info.productIdentifier(), 4, 16, QLatin1Char('0'));
        }
        list << PortEntry{info.systemLocation(), label};
    }
    return list;
}

void PortScanner::rescan()
{
    QList<PortEntry> now = scan();
    if (now == m_ports)
        return;
    m_ports = now;
    Q_EMIT portsChanged();
}

} // namespace stepdeck::ui
