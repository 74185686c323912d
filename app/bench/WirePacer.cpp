#include "WirePacer.h"
#include <cmath>

namespace stepdeck::bench {

WirePacer::WirePacer(double characterUs, std::function<void(const QByteArray&)> deliver,
                     QObject* parent, Delivery delivery)
    : QObject(parent), m_characterNs(characterUs * 1000.0), m_delivery(delivery),
      m_deliver(std::move(deliver)), m_wire(characterUs), m_wakeup([this] { release(); }, this)
{}

void WirePacer::push(const QByteArray& bytes)
{
    if (bytes.isEmpty())
        return;
    const qint64 start = m_wire.write(bytes.size(), PreciseWakeup::nowNs());
    m_chunks.push_back({bytes, start});
    if (!m_wakeup.isArmed())
        release();
}

void WirePacer::release()
{
    // Woken early by the wake-up's mean latency (below): what is due by then is delivered now,
    // so deliveries are on time on average instead of late by that latency.
    const qint64 horizon = PreciseWakeup::nowNs() + kCoalesceNs + m_wakeup.latencyNs();
    QByteArray out;
    while (!m_chunks.empty()) {
        Chunk& chunk = m_chunks.front();
        // Bytes whose last bit has arrived by the horizon.
        const qint64 arrived =
            qMin<qint64>(chunk.bytes.size(),
                         qint64(std::floor(double(horizon - chunk.startNs) / m_characterNs)));
        if (m_delivery == Delivery::WholeWrites) {
            if (arrived < chunk.bytes.size())
                break;
            // Each write on its own, as late as the machine may be.
            const QByteArray whole = std::move(chunk.bytes);
            m_chunks.pop_front();
            m_deliver(whole);
            continue;
        }
        if (arrived <= 0)
            break;
        out += chunk.bytes.left(arrived);
        if (arrived == chunk.bytes.size()) {
            m_chunks.pop_front();
            continue;
        }
        chunk.bytes.remove(0, arrived);
        chunk.startNs += qint64(m_characterNs * double(arrived));
        break;
    }
    if (!out.isEmpty())
        m_deliver(out);
    if (m_chunks.empty())
        return;
    const Chunk& next = m_chunks.front();
    const qsizetype characters = m_delivery == Delivery::WholeWrites ? next.bytes.size() : 1;
    const qint64 due = next.startNs + qint64(std::ceil(m_characterNs * double(characters)));
    m_wakeup.at(due - m_wakeup.latencyNs());
}

} // namespace stepdeck::bench
