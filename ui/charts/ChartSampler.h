#pragma once
#include "ChartAxes.h"
#include "model/MachineStatus.h"
#include <QElapsedTimer>
#include <QObject>
#include <QVector>

namespace stepdeck::ui {

// One point in time of the charts: positions and commanded velocities per axis, temperature
// and poll rate.
struct ChartSample
{
    double t = 0; // seconds since sampling started
    QMap<Axis, double> position;
    QMap<Axis, double> velocity;
    double temperature = qQNaN();
    double pollRate = 0;
};

// Thins the status stream to at most one sample per interval and keeps a bounded history.
class ChartSampler : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxSamples = 36000; // one hour at 10 Hz

    explicit ChartSampler(QObject* parent = nullptr);

    void setInterval(int ms) { m_intervalMs = ms; }
    void add(const MachineStatus& status, double pollRate);
    const QVector<ChartSample>& samples() const { return m_samples; }
    QVector<ChartSample> window(double seconds) const; // the newest `seconds`
    void clear();
    // CSV of the given samples: header and one row per sample.
    static QString toCsv(const QVector<ChartSample>& samples, const QList<ChartAxis>& axes);

private:
    QElapsedTimer m_clock;
    qint64 m_lastMs = -1;
    int m_intervalMs = 100;
    QVector<ChartSample> m_samples;
};

} // namespace stepdeck::ui
