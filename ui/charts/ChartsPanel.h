#pragma once
#include "charts/ChartAxes.h"
#include "charts/ChartSampler.h"
#include <QWidget>

class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QLineSeries;
class QTimer;
class QValueAxis;

namespace stepdeck::ui {

class MachineContext;

// Position and commanded velocity per axis over time, temperature and poll rate (Qt Charts),
// with a time window, pause, and export of the visible data to CSV and the charts to PNG.
class ChartsPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ChartsPanel(MachineContext* context, QWidget* parent = nullptr);

    ChartSampler* sampler() const { return m_sampler; }
    double windowSeconds() const;
    bool exportCsv(const QString& path, QString* error) const;
    bool exportPng(const QString& path, QString* error);
    QCheckBox* pauseCheck() const { return m_pause; }
    int pointCount(int chart) const; // points shown in chart 0..3 (tests)
    // What the Position and Commanded velocity charts plot per axis, and in which unit.
    const QList<ChartAxis>& plottedAxes() const { return m_axes; }

public Q_SLOTS:
    void refresh();
    // Whether the panel is on screen where visibility alone does not tell: a dock behind
    // another tab stays "visible" to QWidget (MainWindow feeds QDockWidget::visibilityChanged).
    void setOnScreen(bool onScreen);
    void exportCsvAs();
    void exportPngAs();

protected:
    // The charts redraw only while visible (issue 10, idle cost: a chart in a hidden tab
    // re-plotting at 4 Hz cost more than the rest of the window); samples are still collected,
    // and showing the panel brings it up to date at once.
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void updateTimer();
    bool m_onScreen = true;
    struct Plot
    {
        QChart* chart = nullptr;
        QChartView* view = nullptr;
        QValueAxis* x = nullptr;
        QValueAxis* y = nullptr;
        QList<QLineSeries*> series;
    };
    Plot makePlot(const QString& title, const QString& unit, const QStringList& names);
    void rebuild();
    void fill(Plot& plot, const QVector<ChartSample>& samples,
              const std::function<double(const ChartSample&, int)>& value);

    MachineContext* m_context;
    ChartSampler* m_sampler;
    QWidget* m_grid;
    QList<Plot> m_plots;
    QComboBox* m_window;
    QCheckBox* m_pause;
    QTimer* m_timer;
    QVector<ChartSample> m_shown;
    QList<ChartAxis> m_axes;
};

} // namespace stepdeck::ui
