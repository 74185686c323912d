#pragma once
#include <QList>
#include <QString>

namespace stepdeck {

// One serial port as the system lists it (QSerialPortInfo). Pseudo-terminals are never
// listed: the GUI and CLI take a typed path for those.
struct SerialPortListing
{
    QString path;        // what the transport opens ("/dev/ttyUSB0")
    QString name;        // "ttyUSB0"
    QString description; // "FT232R USB UART", may be empty
    QString manufacturer;
    // The USB identity, when the port is a USB device (vendor and product id known).
    bool usb = false;
    quint16 vendorId = 0;
    quint16 productId = 0;
    QString serialNumber;

    QString vidPid() const; // "0403:6001", empty unless usb
};

// The serial ports present now. Blocking (udev/sysfs, can take tens of milliseconds): the GUI
// calls it from a worker thread (ui/connection/PortScanner), the CLI's `ports` directly.
QList<SerialPortListing> listSerialPorts();

} // namespace stepdeck
