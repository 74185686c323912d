#pragma once
#include <QCoreApplication>
#include <QString>

namespace stepdeck {

// Why a serial device node cannot be opened, in the user's terms. QSerialPort reports both
// "access denied" (EACCES: the user is not in the device's group) and "locked by another
// program" as PermissionError; the probe tells them apart and names the group to join
// (`dialout` for /dev/ttyS*, /dev/ttyUSB* and /dev/ttyACM* on Debian). Shared by the GUI and
// stepdeck-cli through SerialTransport's error text.
struct SerialPortAccess
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::SerialPortAccess)

public:
    QString device;              // the path as given (may be a /dev/serial/by-id/ link)
    QString deviceGroup;         // the owning group of the device node; empty when unknown
    QString userName;            // who runs this process; empty when unknown
    bool accessible = false;     // read and write permitted: the refusal was a lock, not rights
    bool inGroupNow = false;     // this process already has the device's group
    bool groupListsUser = false; // the group database lists the user (joined, not logged in)

    // The group Debian gives serial devices; named when the device's own cannot be read.
    static QString defaultGroup() { return QStringLiteral("dialout"); }

    // Looks at the device node (stat, access) and the user's groups. No side effects.
    static SerialPortAccess probe(const QString& device);
    // The one-line message for a PermissionError on `device` (pure: from the fields only).
    QString deniedText() const;
};

} // namespace stepdeck
