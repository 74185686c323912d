#include "ChartSampler.h"
#include <QtMath>

namespace stepdeck::ui {

ChartSampler::ChartSampler(QObject* parent) : QObject(parent)
{
    m_clock.start();
}

void ChartSampler::add(const MachineStatus& status, double pollRate)
{
    const qint64 now = m_clock.elapsed();
    if (m_lastMs >= 0 && now - m_lastMs < m_intervalMs)
        return;
    m_lastMs = now;
    ChartSample s;
    s.t = now / 1000.0;
    for (auto it = status.axes.cbegin(); it != status.axes.cend(); ++it) {
        s.position.insert(it.key(), double(it.value().position));
        s.velocity.insert(it.key(), it.value().commandedVelocity);
    }
    if (status.temperatureCelsius)
        s.temperature = *status.temperatureCelsius;
    s.pollRate = pollRate;
    m_samples.append(s);
    if (m_samples.size() > kMaxSamples)
        m_samples.remove(0, m_samples.size() - kMaxSamples);
}

QVector<ChartSample> ChartSampler::window(double seconds) const
{
    if (m_samples.isEmpty())
        return {};
    const double from = m_samples.last().t - seconds;
    auto first = std::lower_bound(m_samples.cbegin(), m_samples.cend(), from,
                                  [](const ChartSample& s, double t) { return s.t < t; });
    return QVector<ChartSample>(first, m_samples.cend());
}

void ChartSampler::clear()
{
    m_samples.clear();
    m_lastMs = -1;
}

QString ChartSampler::toCsv(const QVector<ChartSample>& samples, const QList<ChartAxis>& axes)
{
    // Each axis in what the charts plot it in (issue 31): a machine's axes in their unit, the
    // header naming it ("position_X_mm"), a controller's own axes in steps.
    QStringList header{QStringLiteral("time_s")};
    for (const ChartAxis& a : axes)
        header << QStringLiteral("position_%1_%2").arg(a.name, a.csvUnit());
    for (const ChartAxis& a : axes)
        header << QStringLiteral("velocity_%1_%2_per_s").arg(a.name, a.csvUnit());
    header << QStringLiteral("temperature_c") << QStringLiteral("poll_rate_hz");
    QString out = header.join(QLatin1Char(',')) + QLatin1Char('\n');
    for (const ChartSample& s : samples) {
        QStringList row{QString::number(s.t, 'f', 3)};
        for (const ChartAxis& a : axes)
            row << QString::number(a.position(s.position.value(a.axis)), 'f', a.inMachine ? 4 : 0);
        for (const ChartAxis& a : axes)
            row << QString::number(a.velocity(s.velocity.value(a.axis)), 'f', a.inMachine ? 3 : 1);
        row << (qIsNaN(s.temperature) ? QString() : QString::number(s.temperature, 'f', 1));
        row << QString::number(s.pollRate, 'f', 1);
        out += row.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

} // namespace stepdeck::ui
