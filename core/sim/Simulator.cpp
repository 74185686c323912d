#include "Simulator.h"
#include "Logging.h"
#include "transport/Transport.h"

namespace stepdeck {

Simulator::Simulator(const SimulatorOptions& options, QObject* parent)
    : QObject(parent), m_options(options)
{
    m_paceTimer.setTimerType(Qt::PreciseTimer);
    m_paceTimer.setInterval(1);
    connect(&m_paceTimer, &QTimer::timeout, this, &Simulator::releasePaced);
}

Simulator::~Simulator() = default;

void Simulator::attach(Transport* deviceEnd)
{
    connect(deviceEnd, &Transport::dataReceived, this, &Simulator::receive);
    connect(this, &Simulator::transmit, deviceEnd,
            [deviceEnd](const QByteArray& bytes) { deviceEnd->write(bytes); });
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

void Simulator::send(const QByteArray& reply)
{
    if (m_faults.silent)
        return;
    if (m_faults.dropReplies > 0) {
        --m_faults.dropReplies;
        qCInfo(lcSimulator) << "fault: dropped reply" << reply.toHex();
        return;
    }
    QByteArray bytes = reply;
    if (m_faults.corruptReplies > 0 && !bytes.isEmpty()) {
        --m_faults.corruptReplies;
        bytes[bytes.size() - 1] = char(bytes.at(bytes.size() - 1) ^ 0x5A);
        qCInfo(lcSimulator) << "fault: corrupted reply" << bytes.toHex();
    }
    if (m_faults.delayMs > 0) {
        QTimer::singleShot(m_faults.delayMs, this, [this, bytes] { emitPaced(bytes); });
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
