#include "ContourFeed.h"

namespace stepdeck::motion {

QString ContourFeed::append(const CanonicalMove& move)
{
    QString why;
    {
        QMutexLocker lock(&m_mutex);
        why = m_steps.append(move);
    }
    if (why.isEmpty())
        wake();
    return why;
}

void ContourFeed::close()
{
    {
        QMutexLocker lock(&m_mutex);
        m_steps.close();
    }
    wake();
}

bool ContourFeed::canAppend() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.canAppend();
}

bool ContourFeed::finished() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.finished();
}

int ContourFeed::pull(StepTick* out, int max)
{
    QMutexLocker lock(&m_mutex);
    if (m_held)
        return 0;
    const int n = m_steps.pull(out, max);
    if (n == 0 && max > 0 && !m_steps.finished())
        ++m_starved;
    return n;
}

void ContourFeed::setHeld(bool held)
{
    {
        QMutexLocker lock(&m_mutex);
        if (m_held == held)
            return;
        m_held = held;
    }
    if (!held)
        wake();
}

bool ContourFeed::isHeld() const
{
    QMutexLocker lock(&m_mutex);
    return m_held;
}

qint64 ContourFeed::starvedPulls() const
{
    QMutexLocker lock(&m_mutex);
    return m_starved;
}

void ContourFeed::setStepLimits(int slot, const QString& name, qint64 minimum, qint64 maximum)
{
    QMutexLocker lock(&m_mutex);
    m_steps.setStepLimits(slot, name, minimum, maximum);
}

QString ContourFeed::fault() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.fault();
}

void ContourFeed::setFeedFactor(double factor)
{
    QMutexLocker lock(&m_mutex);
    m_steps.setFeedFactor(factor);
}

double ContourFeed::tickRate() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.tickRate();
}

qint64 ContourFeed::ticks() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.ticks();
}

double ContourFeed::queuedSeconds() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.queuedSeconds();
}

qint64 ContourFeed::movesDone() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.movesDone();
}

int ContourFeed::currentLine() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.currentLine();
}

StepPosition ContourFeed::steps() const
{
    QMutexLocker lock(&m_mutex);
    return m_steps.steps();
}

void ContourFeed::setWakeUp(std::function<void()> wakeUp)
{
    QMutexLocker lock(&m_mutex);
    m_wakeUp = std::move(wakeUp);
}

void ContourFeed::wake()
{
    std::function<void()> wakeUp;
    {
        QMutexLocker lock(&m_mutex);
        wakeUp = m_wakeUp;
    }
    if (wakeUp)
        wakeUp();
}

} // namespace stepdeck::motion
