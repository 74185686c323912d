#include "PreciseWakeup.h"
#include <QSocketNotifier>
#include <QtGlobal>
#include <ctime>
#include <sys/prctl.h>
#include <sys/timerfd.h>
#include <unistd.h>

namespace stepdeck::bench {

namespace {
constexpr qint64 kNsPerSecond = 1000000000;
}

PreciseWakeup::PreciseWakeup(std::function<void()> fire, QObject* parent)
    : QObject(parent), m_fire(std::move(fire))
{
    // The kernel may defer a sleeping thread's timers by its timer slack (50 us by default), to
    // batch wake-ups; the bench's wire wants them on time. Per thread: the owner's, which is
    // the thread that creates it (the device thread, BenchDevice).
    ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd < 0)
        qFatal("stepdeck-bench: timerfd_create failed");
    m_notifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &PreciseWakeup::onReadable);
}

PreciseWakeup::~PreciseWakeup()
{
    delete m_notifier;
    ::close(m_fd);
}

qint64 PreciseWakeup::nowNs()
{
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return qint64(ts.tv_sec) * kNsPerSecond + ts.tv_nsec;
}

void PreciseWakeup::at(qint64 monotonicNs)
{
    // An all-zero it_value disarms the timer: the earliest time armed is 1 ns.
    const qint64 ns = qMax<qint64>(1, monotonicNs);
    itimerspec spec{};
    spec.it_value.tv_sec = time_t(ns / kNsPerSecond);
    spec.it_value.tv_nsec = long(ns % kNsPerSecond);
    ::timerfd_settime(m_fd, TFD_TIMER_ABSTIME, &spec, nullptr);
    m_armed = true;
    m_armedForNs = ns > nowNs() ? ns : 0;
}

void PreciseWakeup::cancel()
{
    itimerspec spec{};
    ::timerfd_settime(m_fd, TFD_TIMER_ABSTIME, &spec, nullptr);
    m_armed = false;
}

void PreciseWakeup::onReadable()
{
    quint64 expirations = 0;
    if (::read(m_fd, &expirations, sizeof expirations) != sizeof expirations)
        return; // disarmed or re-armed since it became readable
    m_armed = false;
    if (m_armedForNs > 0) {
        const qint64 late = qBound<qint64>(0, nowNs() - m_armedForNs, kMaxLatencyNs);
        m_latencyNs += (late - m_latencyNs) / 16;
    }
    m_fire();
}

} // namespace stepdeck::bench
