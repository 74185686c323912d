#include "Simulator.h"
#include "Logging.h"
#include "transport/Transport.h"
#include <limits>

namespace stepdeck {

namespace {
constexpr int kNoiseTickMs = 10;
}

Simulator::Simulator(const SimulatorOptions& options, QObject* parent)
    : QObject(parent), m_options(options), m_faultRng(options.seed),
      m_noiseRng(options.seed ^ 0x9E3779B9u)
{
    m_paceTimer.setTimerType(Qt::PreciseTimer);
    m_paceTimer.setInterval(1);
    connect(&m_paceTimer, &QTimer::timeout, this, &Simulator::releasePaced);
    m_noiseTimer.setInterval(kNoiseTickMs);
    connect(&m_noiseTimer, &QTimer::timeout, this, &Simulator::emitNoise);
    m_freezeTimer.setSingleShot(true);
    connect(&m_freezeTimer, &QTimer::timeout, this, [this] {
        qCInfo(lcSimulator) << "fault: frozen, answering nothing from now on";
        m_faults.silent = true;
        m_counts.frozen = true;
    });
}

Simulator::~Simulator() = default;

void Simulator::attach(Transport* deviceEnd)
{
    connect(deviceEnd, &Transport::dataReceived, this, &Simulator::receive);
    connect(this, &Simulator::transmit, deviceEnd,
            [deviceEnd](const QByteArray& bytes) { deviceEnd->write(bytes); });
}

bool Simulator::isStopFrame(const QByteArray&) const
{
    return false;
}

void Simulator::noteReceived(const QByteArray& frame)
{
    if (m_received.size() >= kReceivedLogSize)
        m_received.remove(0, kReceivedLogSize / 4); // amortised: drop the oldest quarter
    m_received.append(frame);
}

void Simulator::setPacing(bool enabled, const LineSettings& line)
{
    m_options.paceOutput = enabled;
    m_options.line = line;
}

void Simulator::setNoise(double bytesPerSecond)
{
    m_noiseRate = qIsFinite(bytesPerSecond) ? qMax(0.0, bytesPerSecond) : 0.0;
    m_noiseCredit = 0;
    m_noiseClock.start();
    if (m_noiseRate > 0)
        m_noiseTimer.start();
    else
        m_noiseTimer.stop();
}

void Simulator::freezeAfter(qint64 ms)
{
    m_freezeAfterMs = ms;
    m_freezeTimer.stop();
    if (ms < 0 && m_counts.frozen) {
        m_faults.silent = false;
        m_counts.frozen = false;
    }
}

bool Simulator::chance(double probability)
{
    return probability > 0 && m_faultRng.generateDouble() < probability;
}

void Simulator::emitNoise()
{
    m_noiseCredit += m_noiseRate * double(m_noiseClock.restart()) / 1000.0;
    const int count = int(m_noiseCredit);
    if (count <= 0)
        return;
    m_noiseCredit -= count;
    QByteArray noise(count, Qt::Uninitialized);
    for (char& c : noise)
        c = char(m_noiseRng.bounded(256));
    m_counts.noiseBytes += count;
    emitPaced(noise);
}

void Simulator::send(const QByteArray& reply)
{
    if (m_freezeAfterMs >= 0 && !m_freezeTimer.isActive() && !m_counts.frozen)
        m_freezeTimer.start(int(qMin<qint64>(m_freezeAfterMs, std::numeric_limits<int>::max())));
    if (m_faults.silent)
        return;
    ++m_counts.replies;
    // The three decisions are drawn for every reply: with the same seed, options and traffic
    // a run injects the same faults into the same replies.
    const bool drop = chance(m_faults.dropProbability);
    const bool corrupt = chance(m_faults.corruptProbability);
    const bool delay = chance(m_faults.delayProbability) && m_faults.delayMaxMs > 0;
    if (m_faults.dropReplies > 0 || drop) {
        if (m_faults.dropReplies > 0)
            --m_faults.dropReplies;
        ++m_counts.dropped;
        qCInfo(lcSimulator) << "fault: dropped reply" << reply.toHex();
        return;
    }
    QByteArray bytes = reply;
    if (m_faults.corruptReplies > 0 && !bytes.isEmpty()) {
        --m_faults.corruptReplies;
        bytes[bytes.size() - 1] = char(bytes.at(bytes.size() - 1) ^ 0x5A);
        ++m_counts.corrupted;
        qCInfo(lcSimulator) << "fault: corrupted reply" << bytes.toHex();
    } else if (corrupt && !bytes.isEmpty()) {
        const int at = int(m_faultRng.bounded(int(bytes.size())));
        bytes[at] = char(quint8(bytes.at(at)) ^ quint8(1 + m_faultRng.bounded(255)));
        ++m_counts.corrupted;
        qCInfo(lcSimulator) << "fault: corrupted reply" << bytes.toHex();
    }
    int delayMs = m_faults.delayMs;
    if (delay) {
        delayMs += 1 + int(m_faultRng.bounded(m_faults.delayMaxMs));
        ++m_counts.delayed;
    }
    if (delayMs > 0) {
        QTimer::singleShot(delayMs, this, [this, bytes] { emitPaced(bytes); });
        return;
    }
    emitPaced(bytes);
}

void Simulator::sendUnsolicited(const QByteArray& bytes)
{
    if (!m_faults.silent)
        emitPaced(bytes);
}

void Simulator::emitPaced(const QByteArray& bytes)
{
    if (!m_options.paceOutput) {
        Q_EMIT transmit(bytes);
        return;
    }
    if (m_paced.isEmpty()) {
        if (!m_paceClock.isValid())
            m_paceClock.start();
        m_lastReleaseUs = m_paceClock.nsecsElapsed() / 1000;
        m_paceCredit = 0;
    }
    m_paced += bytes;
    if (!m_paceTimer.isActive())
        m_paceTimer.start();
}

void Simulator::releasePaced()
{
    const qint64 nowUs = m_paceClock.nsecsElapsed() / 1000;
    m_paceCredit += (nowUs - m_lastReleaseUs) / m_options.line.characterTimeUs();
    m_lastReleaseUs = nowUs;
    const int count = qMin<qsizetype>(m_paced.size(), qsizetype(m_paceCredit));
    if (count > 0) {
        m_paceCredit -= count;
        const QByteArray out = m_paced.left(count);
        m_paced.remove(0, count);
        Q_EMIT transmit(out);
    }
    if (m_paced.isEmpty())
        m_paceTimer.stop();
}

} // namespace stepdeck
