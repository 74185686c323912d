#include "PortScanner.h"
#include "transport/PortListing.h"
#include <QThread>

namespace stepdeck::ui {

PortScanner::PortScanner(QObject* parent, ScanFunction scanFunction)
    : QObject(parent), m_thread(new QThread(this)), m_worker(new QObject),
      m_scan(scanFunction ? std::move(scanFunction) : ScanFunction(&PortScanner::scan))
{
    m_thread->setObjectName(QStringLiteral("PortScanner"));
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    m_thread->start(QThread::LowPriority);
    m_timer.setInterval(2000);
    connect(&m_timer, &QTimer::timeout, this, &PortScanner::rescan);
    m_timer.start();
    rescan();
}

PortScanner::~PortScanner()
{
    m_thread->quit();
    m_thread->wait();
}

void PortScanner::setScanFunction(ScanFunction scanFunction)
{
    QMutexLocker lock(&m_scanMutex);
    m_scan = std::move(scanFunction);
}

QList<PortEntry> PortScanner::scan()
{
    QList<PortEntry> list;
    for (const SerialPortListing& port : listSerialPorts()) {
        PortEntry entry;
        entry.path = port.path;
        entry.label = port.name;
        if (!port.description.isEmpty())
            entry.label += QStringLiteral(" \u2013 ") + port.description;
        if (port.usb) {
            entry.usb = true;
            entry.vendorId = port.vendorId;
            entry.productId = port.productId;
            entry.serialNumber = port.serialNumber;
            entry.label += QStringLiteral(" (%1)").arg(port.vidPid());
        }
        list << entry;
    }
    return list;
}

void PortScanner::rescan()
{
    if (m_busy) {
        m_again = true; // one more once the running scan is back
        return;
    }
    m_busy = true;
    QMetaObject::invokeMethod(m_worker, [this] {
        QList<PortEntry> ports;
        {
            QMutexLocker lock(&m_scanMutex);
            if (m_scan)
                ports = m_scan();
        }
        QMetaObject::invokeMethod(
            this, [this, ports] { apply(ports); }, Qt::QueuedConnection);
    });
}

void PortScanner::apply(const QList<PortEntry>& ports)
{
    m_busy = false;
    const bool changed = ports != m_ports;
    m_ports = ports;
    if (changed)
        Q_EMIT portsChanged();
    Q_EMIT scanned(m_ports);
    if (m_again) {
        m_again = false;
        rescan();
    }
}

} // namespace stepdeck::ui
