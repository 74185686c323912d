#pragma once
#include "connection/PortScanner.h"
#include <QObject>

namespace stepdeck::ui {

// Follows the USB device a link was opened on across unplug and replug (issue 10): fed with
// every port list the scanner returns, it says when the same device (VID:PID and serial
// number) is back after it had vanished, under whatever path it came back. A device without
// a serial number is only recognised under its old path (two adapters of one type cannot be
// told apart otherwise). It only watches; reconnecting and the safety rules that go with it
// are the connection bar's. No widgets, no I/O: tests feed it fake lists.
class PortWatcher : public QObject
{
    Q_OBJECT
public:
    // How often a returned device is tried before the watcher gives up (the device node may
    // appear before udev has set its permissions).
    static constexpr int kAttempts = 3;

    explicit PortWatcher(QObject* parent = nullptr);

    // Starts following the device at path, as found in ports; false (and nothing watched)
    // when path is no USB device there.
    bool watch(const QString& path, const QList<PortEntry>& ports);
    void forget();
    bool isWatching() const { return m_watching; }
    // The watched device is absent from the last list.
    bool isGone() const { return m_gone; }
    const PortEntry& device() const { return m_device; }

    // A new port list. Emits deviceReturned when the watched device is present again after a
    // list without it.
    void update(const QList<PortEntry>& ports);
    // The reconnect to a returned device failed: try again on the next list that has it,
    // kAttempts times in all.
    void reconnectFailed();

    bool matches(const PortEntry& entry) const;

Q_SIGNALS:
    void deviceReturned(const QString& path);

private:
    PortEntry m_device;
    bool m_watching = false;
    bool m_gone = false;
    bool m_retry = false;
    int m_attemptsLeft = 0;
};

} // namespace stepdeck::ui
