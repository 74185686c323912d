#include "WirePacer.h"
#include <QtMath>

namespace stepdeck::bench {

WirePacer::WirePacer(double characterUs, std::function<void(const QByteArray&)> deliver,
                     QObject* parent)
    : QObject(parent), m_characterUs(characterUs), m_deliver(std::move(deliver)),
      m_wire(characterUs), m_timer(this)
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &WirePacer::release);
}

void WirePacer::push(const QByteArray& bytes)
{
    if (bytes.isEmpty())
        return;
    const double start = double(m_wire.write(bytes.size(), m_clock.nsecsElapsed())) / 1000.0;
    m_chunks.push_back({bytes, start});
    if (!m_timer.isActive())
        release();
}

void WirePacer::release()
{
    const double horizon = nowUs() + kToleranceUs;
    QByteArray out;
    while (!m_chunks.empty()) {
        Chunk& chunk = m_chunks.front();
        const qsizetype arrived = qMin<qsizetype>(
            chunk.bytes.size(), qsizetype(qFloor((horizon - chunk.startUs) / m_characterUs)));
        if (arrived <= 0)
            break;
        out += chunk.bytes.left(arrived);
        if (arrived == chunk.bytes.size()) {
            m_chunks.pop_front();
            continue;
        }
        chunk.bytes.remove(0, arrived);
        chunk.startUs += m_characterUs * double(arrived);
        break;
    }
    if (!out.isEmpty())
        m_deliver(out);
    if (!m_chunks.empty()) {
        const double due = m_chunks.front().startUs + m_characterUs;
        m_timer.start(qMax(0, qCeil((due - kToleranceUs - nowUs()) / 1000.0)));
    }
}

} // namespace stepdeck::bench
