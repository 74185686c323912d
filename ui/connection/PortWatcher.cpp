#include "PortWatcher.h"

namespace stepdeck::ui {

PortWatcher::PortWatcher(QObject* parent) : QObject(parent) {}

bool PortWatcher::watch(const QString& path, const QList<PortEntry>& ports)
{
    forget();
    for (const PortEntry& entry : ports) {
        if (entry.path == path && entry.usb) {
            m_device = entry;
            m_watching = true;
            return true;
        }
    }
    return false;
}

void PortWatcher::forget()
{
    m_device = {};
    m_watching = false;
    m_gone = false;
    m_retry = false;
    m_attemptsLeft = 0;
}

bool PortWatcher::matches(const PortEntry& entry) const
{
    if (!entry.usb || entry.vendorId != m_device.vendorId ||
        entry.productId != m_device.productId || entry.serialNumber != m_device.serialNumber)
        return false;
    // Without a serial number only the old path tells this adapter from another of its type.
    return !m_device.serialNumber.isEmpty() || entry.path == m_device.path;
}

void PortWatcher::update(const QList<PortEntry>& ports)
{
    if (!m_watching)
        return;
    const PortEntry* found = nullptr;
    for (const PortEntry& entry : ports) {
        if (matches(entry)) {
            found = &entry;
            break;
        }
    }
    if (!found) {
        if (!m_gone)
            m_attemptsLeft = kAttempts;
        m_gone = true;
        m_retry = false;
        return;
    }
    if (!m_gone && !m_retry)
        return;
    if (m_attemptsLeft <= 0) {
        m_retry = false;
        return;
    }
    m_gone = false;
    m_retry = false;
    --m_attemptsLeft;
    m_device.path = found->path;
    m_device.label = found->label;
    Q_EMIT deviceReturned(found->path);
}

void PortWatcher::reconnectFailed()
{
    if (m_watching && m_attemptsLeft > 0)
        m_retry = true;
}

} // namespace stepdeck::ui
