#include "PortListing.h"
#include <QSerialPortInfo>

namespace stepdeck {

QString SerialPortListing::vidPid() const
{
    if (!usb)
        return {};
    return QStringLiteral("%1:%2")
        .arg(vendorId, 4, 16, QLatin1Char('0'))
        .arg(productId, 4, 16, QLatin1Char('0'));
}

QList<SerialPortListing> listSerialPorts()
{
    QList<SerialPortListing> list;
    const auto infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo& info : infos) {
        SerialPortListing port;
        port.path = info.systemLocation();
        port.name = info.portName();
        port.description = info.description();
        port.manufacturer = info.manufacturer();
        if (info.hasVendorIdentifier() && info.hasProductIdentifier()) {
            port.usb = true;
            port.vendorId = info.vendorIdentifier();
            port.productId = info.productIdentifier();
        }
        // The CLI lists the serial number of any port; the GUI follows it only on USB ports.
        port.serialNumber = info.serialNumber();
        list << port;
    }
    return list;
}

} // namespace stepdeck
