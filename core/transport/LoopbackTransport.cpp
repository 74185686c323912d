#include "LoopbackTransport.h"
#include "Logging.h"
#include <QMetaObject>

namespace stepdeck {

LoopbackTransport::LoopbackTransport(QObject* parent) : Transport(parent) {}

std::pair<LoopbackTransport*, LoopbackTransport*> LoopbackTransport::createPair(QObject* parent)
{
    auto* a = new LoopbackTransport(parent);
    auto* b = new LoopbackTransport(parent);
    a->setPeer(b);
    b->setPeer(a);
    return {a, b};
}

void LoopbackTransport::open(const LineSettings& settings)
{
    m_settings = settings;
    m_open = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (m_open)
                Q_EMIT opened();
        },
        Qt::QueuedConnection);
}

void LoopbackTransport::close()
{
    if (!m_open)
        return;
    m_open = false;
    Q_EMIT closed();
}

qint64 LoopbackTransport::write(const QByteArray& bytes)
{
    if (!m_open || bytes.isEmpty())
        return m_open ? 0 : -1;
    if (m_peer) {
        LoopbackTransport* peer = m_peer;
        const quint64 gen = m_generation;
        QPointer<LoopbackTransport> self(this);
        QMetaObject::invokeMethod(
            peer,
            [peer, bytes, gen, self] {
                if (self && self->m_generation != gen)
                    return; // discarded before it "left the wire"
                peer->deliver(bytes, gen);
            },
            Qt::QueuedConnection);
    }
    QMetaObject::invokeMethod(
        this, [this, n = bytes.size()] { Q_EMIT bytesWritten(n); }, Qt::QueuedConnection);
    return bytes.size();
}

void LoopbackTransport::discardOutput()
{
    ++m_generation;
}

void LoopbackTransport::deliver(const QByteArray& bytes, quint64)
{
    // A device end that was never opened still receives (simulators attach without opening).
    Q_EMIT dataReceived(bytes);
}

void LoopbackTransport::simulateFailure(const QString& reason)
{
    if (!m_open)
        return;
    m_open = false;
    qCWarning(lcTransport) << "loopback failure:" << reason;
    Q_EMIT failed(reason);
    Q_EMIT closed();
}

} // namespace stepdeck
