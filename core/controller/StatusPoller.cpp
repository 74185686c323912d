#include "StatusPoller.h"
#include "Logging.h"

namespace stepdeck {

namespace {
constexpr qint64 kRateWindowMs = 1000;
constexpr qint64 kRateEmitPeriodMs = 500;
} // namespace

StatusPoller::StatusPoller(QObject* parent) : QObject(parent), m_timer(this)
{
    // Parented to this so moveToThread() takes the timer along to the controller thread.
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &StatusPoller::onTick);
    m_clock.start();
}

void StatusPoller::setInterval(int ms)
{
    m_intervalMs = qMax(1, ms);
    schedule();
}

void StatusPoller::setExpedited(bool expedited)
{
    if (expedited == m_expedited)
        return;
    m_expedited = expedited;
    schedule();
}

int StatusPoller::effectiveInterval() const
{
    return m_expedited ? qMin(m_intervalMs, kExpeditedIntervalMs) : m_intervalMs;
}

void StatusPoller::setMissLimit(int misses)
{
    m_missLimit = qMax(1, misses);
}

void StatusPoller::start()
{
    m_active = true;
    m_misses = 0;
    schedule();
}

void StatusPoller::stop()
{
    m_active = false;
    m_inFlight = false;
    m_expedited = false;
    m_timer.stop();
    m_completions.clear();
    maybeEmitRate(true);
}

bool StatusPoller::isDue() const
{
    if (!m_active || m_inFlight)
        return false;
    return m_lastStartMs < 0 || now() - m_lastStartMs >= effectiveInterval();
}

void StatusPoller::pollStarted()
{
    m_inFlight = true;
    m_lastStartMs = now();
    m_timer.stop(); // nothing is due while a poll is in flight
}

void StatusPoller::pollFinished(bool answered)
{
    if (!m_inFlight)
        return; // a late or duplicate report: the poll was already accounted for
    m_inFlight = false;
    if (answered) {
        m_misses = 0;
        m_completions.push_back(now());
    } else {
        ++m_misses;
        qCDebug(lcPoller) << "poll unanswered," << m_misses << "in a row";
        // Exactly once per outage: further misses keep counting but do not re-report.
        if (m_misses == m_missLimit) {
            qCWarning(lcPoller) << m_misses << "polls unanswered: link lost";
            Q_EMIT linkLost(m_misses);
        }
    }
    maybeEmitRate(false);
    schedule();
}

double StatusPoller::achievedRateHz() const
{
    const qint64 t = now();
    int count = 0;
    for (auto it = m_completions.crbegin(); it != m_completions.crend(); ++it) {
        if (t - *it > kRateWindowMs)
            break;
        ++count;
    }
    return count * 1000.0 / kRateWindowMs;
}

void StatusPoller::onTick()
{
    if (!isDue()) {
        schedule();
        return;
    }
    maybeEmitRate(false);
    Q_EMIT pollDue();
    // The adapter starts the poll when its line is free (commands go first). Until it does,
    // remind it once per interval so a poll skipped for a busy line is not lost for good.
    if (m_active && !m_inFlight)
        m_timer.start(effectiveInterval());
}

void StatusPoller::schedule()
{
    if (!m_active || m_inFlight) {
        m_timer.stop();
        return;
    }
    const qint64 remaining =
        m_lastStartMs < 0 ? 0 : qMax<qint64>(0, m_lastStartMs + effectiveInterval() - now());
    m_timer.start(int(remaining));
}

void StatusPoller::maybeEmitRate(bool force)
{
    const qint64 t = now();
    while (!m_completions.empty() && t - m_completions.front() > kRateWindowMs)
        m_completions.pop_front();
    if (!force && m_lastRateEmitMs >= 0 && t - m_lastRateEmitMs < kRateEmitPeriodMs)
        return;
    const double hz = achievedRateHz();
    if (hz == m_lastRateHz)
        return;
    m_lastRateEmitMs = t;
    m_lastRateHz = hz;
    Q_EMIT rateChanged(hz);
}

} // namespace stepdeck
