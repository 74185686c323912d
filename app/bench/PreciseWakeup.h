#pragma once
#include <QObject>
#include <functional>

class QSocketNotifier;

namespace stepdeck::bench {

// A one-shot wake-up at an absolute time with microsecond precision, in the thread that owns
// it, without busy-waiting: a Linux timerfd (CLOCK_MONOTONIC, absolute) watched by the event
// loop through a QSocketNotifier. QTimer takes whole milliseconds, which would put up to a
// millisecond on every character the bench's wire delivers (WirePacer).
class PreciseWakeup : public QObject
{
public:
    explicit PreciseWakeup(std::function<void()> fire, QObject* parent = nullptr);
    ~PreciseWakeup() override;
    PreciseWakeup(const PreciseWakeup&) = delete;
    PreciseWakeup& operator=(const PreciseWakeup&) = delete;

    static qint64 nowNs(); // CLOCK_MONOTONIC, the clock at() takes

    void at(qint64 monotonicNs); // re-arms; a time in the past fires at once
    void cancel();
    bool isArmed() const { return m_armed; }
    // How late the wake-ups came, on average (an exponential mean over the last ~16 whose time
    // was still ahead when armed), at most kMaxLatencyNs: a caller that wants to be on time on
    // average arms this much early.
    qint64 latencyNs() const { return m_latencyNs; }
    static constexpr qint64 kMaxLatencyNs = 100000;

private:
    void onReadable();

    std::function<void()> m_fire;
    int m_fd = -1;
    QSocketNotifier* m_notifier = nullptr;
    bool m_armed = false;
    qint64 m_armedForNs = 0; // the time armed for, when it was still ahead; 0 otherwise
    qint64 m_latencyNs = 0;
};

} // namespace stepdeck::bench
