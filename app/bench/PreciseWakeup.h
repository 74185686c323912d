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

private:
    void onReadable();

    std::function<void()> m_fire;
    int m_fd = -1;
    QSocketNotifier* m_notifier = nullptr;
    bool m_armed = false;
};

} // namespace stepdeck::bench
