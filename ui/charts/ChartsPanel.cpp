#include "ChartsPanel.h"
#include "common/Dialogs.h"
#include "machine/MachineContext.h"
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QGridLayout>
#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <QValueAxis>
#include <QtMath>

namespace stepdeck::ui {

ChartsPanel::ChartsPanel(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_sampler(new ChartSampler(this)),
      m_grid(new QWidget(this)), m_window(new QComboBox(this)),
      m_pause(new QCheckBox(tr("Pause"), this)), m_timer(new QTimer(this))
{
    for (int s : {10, 30, 60, 300})
        m_window->addItem(s < 60 ? tr("%1 s").arg(s) : tr("%1 min").arg(s / 60), s);
    m_window->setCurrentIndex(1);
    auto* csv = new QPushButton(tr("Export CSV\u2026"), this);
    auto* png = new QPushButton(tr("Export PNG\u2026"), this);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Time window:"), this));
    bar->addWidget(m_window);
    bar->addWidget(m_pause);
    bar->addStretch(1);
    bar->addWidget(csv);
    bar->addWidget(png);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_grid, 1);
    new QGridLayout(m_grid);
    m_grid->layout()->setContentsMargins(0, 0, 0, 0);

    connect(csv, &QPushButton::clicked, this, &ChartsPanel::exportCsvAs);
    connect(png, &QPushButton::clicked, this, &ChartsPanel::exportPngAs);
    connect(m_window, &QComboBox::currentIndexChanged, this, &ChartsPanel::refresh);
    connect(context, &MachineContext::modelChanged, this, &ChartsPanel::rebuild);
    connect(context->session(), &ControllerSession::statusChanged, this,
            [this](const MachineStatus& s) {
                if (m_context->isConnected())
                    m_sampler->add(s, m_context->session()->pollRateHz());
            });
    m_timer->setInterval(250);
    connect(m_timer, &QTimer::timeout, this, &ChartsPanel::refresh);
    rebuild();
}

ChartsPanel::Plot ChartsPanel::makePlot(const QString& title, const QString& unit,
                                        const QStringList& names)
{
    Plot plot;
    plot.chart = new QChart;
    plot.chart->setTitle(title);
    plot.chart->setMargins(QMargins(4, 4, 4, 4));
    plot.chart->legend()->setVisible(names.size() > 1);
    plot.chart->legend()->setAlignment(Qt::AlignRight); // keeps the height for the plot
    plot.x = new QValueAxis;
    plot.x->setTitleText(tr("time [s]"));
    plot.x->setLabelFormat(QStringLiteral("%.0f"));
    plot.x->setTickCount(7);
    plot.y = new QValueAxis;
    plot.y->setTitleText(unit);
    plot.y->setLabelFormat(QStringLiteral("%g"));
    plot.chart->addAxis(plot.x, Qt::AlignBottom);
    plot.chart->addAxis(plot.y, Qt::AlignLeft);
    for (const QString& name : names) {
        auto* series = new QLineSeries;
        series->setName(name);
        plot.chart->addSeries(series);
        series->attachAxis(plot.x);
        series->attachAxis(plot.y);
        series->setUseOpenGL(false);
        plot.series << series;
    }
    plot.view = new QChartView(plot.chart, m_grid);
    plot.view->setRenderHint(QPainter::Antialiasing);
    plot.view->setMinimumSize(260, 200);
    return plot;
}

void ChartsPanel::rebuild()
{
    for (const Plot& p : std::as_const(m_plots))
        delete p.view; // owns its chart
    m_plots.clear();
    // Each axis in its machine unit (mm, deg), else in the model's position unit (steps;
    // laser axes: units, issue 16).
    m_axes = chartAxes(*m_context);
    QStringList axes;
    for (const ChartAxis& a : std::as_const(m_axes))
        axes << a.name;
    const QStringList units = chartUnits(m_axes); // several: each named in the title
    QStringList rates;
    for (const QString& unit : units)
        rates << tr("%1/s").arg(unit);
    m_plots << makePlot(tr("Position"), units.join(QStringLiteral(", ")), axes);
    m_plots << makePlot(tr("Commanded velocity"), rates.join(QStringLiteral(", ")), axes);
    m_plots << makePlot(tr("Temperature"), tr("°C"), {tr("Temperature")});
    m_plots << makePlot(tr("Poll rate"), tr("Hz"), {tr("Poll rate")});
    auto* grid = static_cast<QGridLayout*>(m_grid->layout());
    for (int i = 0; i < m_plots.size(); ++i)
        grid->addWidget(m_plots[i].view, i / 2, i % 2);
    m_sampler->clear();
    refresh();
}

double ChartsPanel::windowSeconds() const
{
    return m_window->currentData().toDouble();
}

void ChartsPanel::fill(Plot& plot, const QVector<ChartSample>& samples,
                       const std::function<double(const ChartSample&, int)>& value)
{
    double lo = qInf();
    double hi = -qInf();
    for (int i = 0; i < plot.series.size(); ++i) {
        QList<QPointF> points;
        points.reserve(samples.size());
        for (const ChartSample& s : samples) {
            const double v = value(s, i);
            if (qIsNaN(v))
                continue;
            points << QPointF(s.t, v);
            lo = qMin(lo, v);
            hi = qMax(hi, v);
        }
        plot.series[i]->replace(points);
    }
    if (lo > hi) {
        lo = 0;
        hi = 1;
    }
    const double pad = qMax(1.0, (hi - lo) * 0.08);
    // Rates and temperatures never go below zero: no padding into negative numbers.
    plot.y->setRange(lo >= 0 ? qMax(0.0, lo - pad) : lo - pad, hi + pad);
    plot.y->applyNiceNumbers(); // round ticks: no repeated labels on a narrow range
    const double end =
        samples.isEmpty() ? windowSeconds() : qMax(samples.last().t, windowSeconds());
    plot.x->setRange(end - windowSeconds(), end);
}

void ChartsPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateTimer();
}

void ChartsPanel::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    updateTimer();
}

void ChartsPanel::setOnScreen(bool onScreen)
{
    m_onScreen = onScreen;
    updateTimer();
}

void ChartsPanel::updateTimer()
{
    const bool shown = isVisible() && m_onScreen;
    if (shown == m_timer->isActive())
        return;
    if (shown) {
        refresh(); // up to date at once
        m_timer->start();
    } else {
        m_timer->stop();
    }
}

void ChartsPanel::refresh()
{
    if (m_pause->isChecked() || m_plots.size() < 4)
        return;
    m_shown = m_sampler->window(windowSeconds());
    const QList<ChartAxis>& axes = m_axes;
    fill(m_plots[0], m_shown, [&](const ChartSample& s, int i) {
        const ChartAxis& a = axes.at(i);
        return a.position(s.position.value(a.axis, qQNaN()));
    });
    fill(m_plots[1], m_shown, [&](const ChartSample& s, int i) {
        const ChartAxis& a = axes.at(i);
        return a.velocity(s.velocity.value(a.axis, qQNaN()));
    });
    fill(m_plots[2], m_shown, [](const ChartSample& s, int) { return s.temperature; });
    fill(m_plots[3], m_shown, [](const ChartSample& s, int) { return s.pollRate; });
}

int ChartsPanel::pointCount(int chart) const
{
    if (chart < 0 || chart >= m_plots.size() || m_plots[chart].series.isEmpty())
        return 0;
    return int(m_plots[chart].series.first()->count());
}

bool ChartsPanel::exportCsv(const QString& path, QString* error) const
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    // The visible data: what the charts show now (frozen while paused).
    file.write(ChartSampler::toCsv(m_shown, chartAxes(*m_context)).toUtf8());
    return true;
}

bool ChartsPanel::exportPng(const QString& path, QString* error)
{
    if (!m_grid->grab().save(path, "PNG")) {
        *error = tr("Cannot write %1").arg(path);
        return false;
    }
    return true;
}

void ChartsPanel::exportCsvAs()
{
    dialogs::saveFile(this, QStringLiteral("charts"), tr("Export CSV"),
                      QStringLiteral("stepdeck-charts.csv"), tr("CSV files (*.csv)"),
                      [this](const QString& path) {
                          QString error;
                          if (!exportCsv(path, &error))
                              dialogs::message(this, QMessageBox::Warning, tr("Export CSV"), error);
                      });
}

void ChartsPanel::exportPngAs()
{
    dialogs::saveFile(this, QStringLiteral("charts"), tr("Export PNG"),
                      QStringLiteral("stepdeck-charts.png"), tr("PNG images (*.png)"),
                      [this](const QString& path) {
                          QString error;
                          if (!exportPng(path, &error))
                              dialogs::message(this, QMessageBox::Warning, tr("Export PNG"), error);
                      });
}

} // namespace stepdeck::ui
