#include "ProgramPreviewView.h"
#include "ProgramPathView.h"
#include "ProgramTimes.h"
#include "common/ElidedLabel.h"
#include <QChart>
#include <QChartView>
#include <QHeaderView>
#include <QLineSeries>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <optional>
#include <utility>

namespace stepdeck::ui {

namespace {
QString unitText(const machine::MachineAxis& axis)
{
    return machine::unitKey(axis.unit);
}

// The soft limits of axis in work coordinates (they are machine coordinates).
std::optional<std::pair<double, double>> workLimits(const machine::MachineAxis& axis,
                                                    const QMap<QString, double>& offsets)
{
    if (!axis.hasSoftLimits())
        return std::nullopt;
    const double offset = offsets.value(axis.name, 0.0);
    return std::make_pair(*axis.softMinimum - offset, *axis.softMaximum - offset);
}
} // namespace

ProgramPreviewView::ProgramPreviewView(QWidget* parent)
    : QWidget(parent), m_path(new ProgramPathView(this)), m_chart(new QChart),
      m_chartView(new QChartView(m_chart, this)), m_extents(new QTableWidget(0, 4, this)),
      m_tabs(new QTabWidget(this)), m_summary(new QWidget(this)),
      m_figures(new ElidedLabel(m_summary)), m_motionNote(new ElidedLabel(this)),
      m_coordinates(new ElidedLabel(m_summary))
{
    setObjectName(QStringLiteral("programPreview"));
    m_chart->legend()->setAlignment(Qt::AlignRight);
    m_chart->setMargins(QMargins(2, 2, 2, 2));
    m_chartView->setObjectName(QStringLiteral("programAxisChart"));
    m_chartView->setRenderHint(QPainter::Antialiasing);
    // Small minimums: the tabs must fit a bottom dock on a 768-pixel screen; larger docks
    // give them more.
    m_chartView->setMinimumSize(120, 60);
    m_extents->setMinimumSize(120, 40);
    m_extents->setObjectName(QStringLiteral("programExtents"));
    m_extents->setHorizontalHeaderLabels(
        {tr("Axis"), tr("Program from"), tr("Program to"), tr("Soft limits")});
    m_extents->verticalHeader()->hide();
    m_extents->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_extents->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_extents->setSelectionMode(QAbstractItemView::NoSelection);
    m_figures->setObjectName(QStringLiteral("programFigures"));
    m_motionNote->setObjectName(QStringLiteral("programMotionNote"));
    m_coordinates->setObjectName(QStringLiteral("programCoordinates"));

    // Tabs, not a column: the page must fit the bottom of a 768-pixel screen.
    m_tabs->setObjectName(QStringLiteral("programPreviewTabs"));
    m_tabs->addTab(m_path, tr("Path"));
    m_tabs->addTab(m_chartView, tr("Axes over time"));
    // How the axes of a block move together stands with the extents (and in the figures'
    // tooltip).
    auto* extents = new QWidget(m_tabs);
    auto* ev = new QVBoxLayout(extents);
    ev->setContentsMargins(0, 0, 0, 0);
    ev->addWidget(m_extents, 1);
    ev->addWidget(m_motionNote);
    m_tabs->addTab(extents, tr("Extents"));
    auto* summary = new QVBoxLayout(m_summary);
    summary->setContentsMargins(0, 0, 0, 0);
    summary->setSpacing(3);
    summary->addWidget(m_figures);
    summary->addWidget(m_coordinates);
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(m_tabs, 1);
    clear(tr("No program checked yet."));
}

void ProgramPreviewView::clearChart()
{
    m_chart->removeAllSeries(); // deletes the series, the "now" line among them
    m_now = nullptr;
    // removeAxis() hands the axis back to the caller (QChart): without the delete every
    // check while typing leaked two axes (found by LeakSanitizer).
    for (QAbstractAxis* axis : m_chart->axes()) {
        m_chart->removeAxis(axis);
        delete axis;
    }
}

void ProgramPreviewView::clear(const QString& reason)
{
    m_path->clearPath(reason);
    clearChart();
    m_extents->setRowCount(0);
    m_figures->setText(reason);
    m_motionNote->clear();
    m_coordinates->clear();
    m_figures->setToolTip(QString());
}

QString ProgramPreviewView::coordinatesText() const
{
    return m_coordinates->text();
}

void ProgramPreviewView::setPreview(const program::ProgramPreview& preview,
                                    const machine::MachineDescription& machine)
{
    m_hasX = machine.axis(QStringLiteral("X")) != nullptr;
    m_hasY = machine.axis(QStringLiteral("Y")) != nullptr;
    m_path->setPreview(preview, machine);
    bool anyView = false;
    for (PreviewViewKind kind : PreviewProjection::kAll)
        anyView = anyView || m_path->isAvailable(kind);
    if (!anyView)
        m_path->clearPath(
            tr("This machine has no two of the axes X, Y and Z: see the other tabs."));
    fillChart(preview, machine);
    fillExtents(preview, machine);
    QStringList zeros;
    for (const machine::MachineAxis& axis : machine.axes)
        if (const auto it = preview.workOffsets.constFind(axis.name);
            it != preview.workOffsets.cend())
            zeros << tr("%1 0 at machine %2 %3")
                         .arg(axis.name)
                         .arg(it.value(), 0, 'f', 3)
                         .arg(unitText(axis));
    m_coordinates->setText(zeros.isEmpty()
                               ? tr("Work coordinates = machine coordinates (no work zero set)")
                               : tr("Work coordinates: %1").arg(zeros.join(QStringLiteral(", "))));
    m_coordinates->setToolTip(
        tr("The program's positions, the path and the extents are work coordinates, as the "
           "position display shows them; the machine moves to work + offset. Soft limits are "
           "shown converted to work coordinates."));
    QString figures =
        tr("%n line(s)", nullptr, preview.lines) + QStringLiteral(" \u00b7 ") +
        tr("%n block(s) run", nullptr, int(qMin<qint64>(preview.blocksRun, INT_MAX))) +
        QStringLiteral(" \u00b7 ") + ProgramTimes::estimatedDuration(preview.estimatedSeconds);
    if (preview.pathDecimated)
        figures += QStringLiteral(" \u00b7 ") + tr("path simplified");
    m_figures->setText(figures);
    m_motionNote->setText(preview.motionNote);
    m_motionNote->setToolTip(preview.motionNote);
    m_figures->setToolTip(preview.motionNote);
}

void ProgramPreviewView::fillChart(const program::ProgramPreview& preview,
                                   const machine::MachineDescription& machine)
{
    clearChart();
    auto* time = new QValueAxis;
    time->setTitleText(tr("s (estimated)"));
    time->setLabelFormat(QStringLiteral("%.0f"));
    auto* value = new QValueAxis;
    value->setLabelFormat(QStringLiteral("%.1f"));
    m_chart->addAxis(time, Qt::AlignBottom);
    m_chart->addAxis(value, Qt::AlignLeft);
    double lo = 0, hi = 0;
    bool any = false;
    for (const machine::MachineAxis& axis : machine.axes) {
        // X and Y are drawn in the path view when the machine has both.
        if ((axis.name == QLatin1String("X") || axis.name == QLatin1String("Y")) && m_hasX &&
            m_hasY)
            continue;
        if (!preview.extents.value(axis.name).moved)
            continue;
        auto* series = new QLineSeries;
        series->setName(QStringLiteral("%1 (%2)").arg(axis.name, unitText(axis)));
        for (const program::PreviewPoint& p : preview.path) {
            const auto it = p.position.constFind(axis.name);
            if (it == p.position.cend())
                continue;
            series->append(p.seconds, it.value());
            lo = any ? qMin(lo, it.value()) : it.value();
            hi = any ? qMax(hi, it.value()) : it.value();
            any = true;
        }
        m_chart->addSeries(series);
        series->attachAxis(time);
        series->attachAxis(value);
    }
    if (hi - lo < 1e-9) {
        lo -= 1;
        hi += 1;
    }
    m_chartMin = lo;
    m_chartMax = hi;
    value->setRange(lo, hi);
    time->setRange(0, qMax(1.0, preview.estimatedSeconds));
    m_now = new QLineSeries;
    m_now->setName(tr("now"));
    m_chart->addSeries(m_now);
    m_now->attachAxis(time);
    m_now->attachAxis(value);
    // The tabs stay (nothing moves); an empty chart says there is nothing to chart.
    m_chart->setTitle(any ? QString() : tr("No axis besides X and Y moves."));
}

void ProgramPreviewView::fillExtents(const program::ProgramPreview& preview,
                                     const machine::MachineDescription& machine)
{
    m_extents->setRowCount(0);
    for (const machine::MachineAxis& axis : machine.axes) {
        const auto it = preview.extents.constFind(axis.name);
        if (it == preview.extents.cend() || !it->moved)
            continue;
        const int row = m_extents->rowCount();
        m_extents->insertRow(row);
        const QString unit = unitText(axis);
        const auto work = workLimits(axis, preview.workOffsets);
        const QString limits = work ? tr("%1 \u2026 %2 %3")
                                          .arg(work->first, 0, 'f', 3)
                                          .arg(work->second, 0, 'f', 3)
                                          .arg(unit)
                                    : tr("none");
        const QStringList cells{
            axis.name, QStringLiteral("%1 %2").arg(it->minimum, 0, 'f', 3).arg(unit),
            QStringLiteral("%1 %2").arg(it->maximum, 0, 'f', 3).arg(unit), limits};
        for (int c = 0; c < cells.size(); ++c)
            m_extents->setItem(row, c, new QTableWidgetItem(cells.at(c)));
    }
}

void ProgramPreviewView::setCurrent(const QMap<QString, double>& positions, double seconds)
{
    m_path->setCurrent(positions);
    if (m_now)
        m_now->replace(QList<QPointF>{{seconds, m_chartMin}, {seconds, m_chartMax}});
}

void ProgramPreviewView::setRunningLine(int line)
{
    m_path->setRunningLine(line);
}

void ProgramPreviewView::clearCurrent()
{
    m_path->setCurrent({});
    m_path->setRunningLine(0);
    if (m_now)
        m_now->clear();
}

QString ProgramPreviewView::figuresText() const
{
    return m_figures->text();
}

QStringList ProgramPreviewView::chartedAxes() const
{
    QStringList out;
    for (QAbstractSeries* s : m_chart->series()) {
        if (s != m_now)
            out << s->name();
    }
    return out;
}

} // namespace stepdeck::ui
