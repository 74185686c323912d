#pragma once
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <deque>

namespace stepdeck {

// Schedules status polls for an adapter. It never has more than one poll in flight and it
// yields the line to commands: it only says a poll is due (pollDue), the adapter starts it
// when its line is free and reports back. N consecutive unanswered polls mean link lost.
class StatusPoller : public QObject
{
    Q_OBJECT
public:
    explicit StatusPoller(QObject* parent = nullptr);

    void setInterval(int ms); // default 50 ms
    int interval() const { return m_intervalMs; }
    // While the adapter waits for a motion to end it polls at most kExpeditedIntervalMs apart
    // (its own interval when that is shorter), so an arrival is seen within a status read or
    // two, not up to an interval later; commands still go first.
    static constexpr int kExpeditedIntervalMs = 10;
    void setExpedited(bool expedited);
    bool isExpedited() const { return m_expedited; }
    int effectiveInterval() const;
    void setMissLimit(int misses); // default 3
    int missLimit() const { return m_missLimit; }

    void start();
    void stop();
    bool isActive() const { return m_active; }

    bool isDue() const; // active, interval elapsed since last start, none in flight
    bool isPollInFlight() const { return m_inFlight; }
    void pollStarted();
    void pollFinished(bool answered); // answered=false: timeout or garbage
    int consecutiveMisses() const { return m_misses; }

    // Completed polls per second over the last second.
    double achievedRateHz() const;

Q_SIGNALS:
    void pollDue();
    void linkLost(int missedPolls);
    void rateChanged(double hz);

private:
    void onTick();
    void schedule();                // arms the timer for the next due time
    void maybeEmitRate(bool force); // rateChanged at most every 500 ms
    qint64 now() const { return m_clock.elapsed(); }

    QTimer m_timer;
    QElapsedTimer m_clock;
    int m_intervalMs = 50;
    int m_missLimit = 3;
    bool m_active = false;
    bool m_expedited = false;
    bool m_inFlight = false;
    qint64 m_lastStartMs = -1;
    int m_misses = 0;
    std::deque<qint64> m_completions; // ms timestamps of answered polls in the last second
    qint64 m_lastRateEmitMs = -1;
    double m_lastRateHz = -1;
};

} // namespace stepdeck
