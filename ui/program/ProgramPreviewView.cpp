#include "ProgramPreviewView.h"
#include "ProgramPathView.h"
#include "ProgramTimes.h"
#include "common/ElidedLabel.h"
#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QFontMetrics>
#include <QHeaderView>
#include <QLineSeries>
#include <QPainter>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
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

// Issue 47 item 12: what lies beyond the soft limits, drawn and written in the colour of the
// check's errors (the check line's and the list's #b00000, a little lighter on the drawing).
const QColor kErrorText(0xb0, 0, 0);
QColor errorColor()
{
    return QColor(210, 0, 0);
}
constexpr int kMaxLimitExits = 100; // rings where the path leaves the soft limits

// Whether a work position lies beyond the axis' soft limits (work limits), with half a step of
// room: the path holds whole steps, the check judged the programmed target.
bool beyond(const machine::MachineAxis& axis, const std::pair<double, double>& work, double at)
{
    const double room = 0.5 / axis.stepsPerUnit;
    return at < work.first - room || at > work.second + room;
}

// Per point of the path whether it lies beyond a soft limit of one of its axes.
QList<bool> beyondLimits(const program::ProgramPreview& preview,
                         const machine::MachineDescription& machine)
{
    struct Limited
    {
        const machine::MachineAxis* axis;
        std::pair<double, double> work;
    };
    QList<Limited> limited;
    for (const machine::MachineAxis& axis : machine.axes)
        if (const auto work = workLimits(axis, preview.workOffsets))
            limited.append(Limited{&axis, *work});
    QList<bool> out;
    out.reserve(preview.path.size());
    for (const program::PreviewPoint& p : preview.path) {
        bool outside = false;
        for (const Limited& l : limited) {
            const auto it = p.position.constFind(l.axis->name);
            if (it != p.position.cend() && beyond(*l.axis, l.work, it.value())) {
                outside = true;
                break;
            }
        }
        out << outside;
    }
    return out;
}
} // namespace

// Over the path view (its child, below its selector and Fit, transparent to the mouse): the
// path of a program with errors where it lies beyond the soft limits (issue 47 item 12), the
// segments to and from such points in the error colour, a ring where the path leaves the
// limits, and a legend line at the top right (the view's own legend is at the bottom left).
// It draws the view's own plane points (ProgramPathView::projected(), whatever view or turn the
// view shows) through the view's own mapping (toWidget), so zoom, pan and turns follow.
class PreviewLimitsOverlay : public QWidget
{
public:
    explicit PreviewLimitsOverlay(ProgramPathView* view) : QWidget(view), m_view(view)
    {
        setObjectName(QStringLiteral("programPreviewLimits"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setFocusPolicy(Qt::NoFocus);
        setGeometry(view->rect());
        view->installEventFilter(this);
        lower(); // under the view's selector and Fit
    }

    void setPath(const QList<program::PreviewPoint>& points, const QList<bool>& outside,
                 const QString& legend)
    {
        static const QString kXyz[3] = {QStringLiteral("X"), QStringLiteral("Y"),
                                        QStringLiteral("Z")};
        m_known.clear();
        m_lines.clear();
        m_known.reserve(points.size());
        m_lines.reserve(points.size());
        for (const program::PreviewPoint& p : points) {
            unsigned known = 0;
            for (unsigned axis = 0; axis < 3; ++axis)
                if (p.position.contains(kXyz[axis]))
                    known |= 1u << axis;
            m_known << known;
            m_lines << p.line;
        }
        m_beyond = outside;
        m_legend = legend;
        m_count = int(std::count(outside.cbegin(), outside.cend(), true));
        update();
    }
    void clear() { setPath({}, {}, QString()); }
    int count() const { return m_count; }
    QList<QPointF> exits() const
    {
        QPainterPath segments;
        QList<QPointF> out;
        inPlane(&segments, &out);
        return out;
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == m_view && event->type() == QEvent::Resize)
            setGeometry(m_view->rect());
        return QWidget::eventFilter(watched, event);
    }

    void paintEvent(QPaintEvent*) override
    {
        QPainterPath segments;
        QList<QPointF> rings;
        if (!inPlane(&segments, &rings))
            return; // nothing beyond, or the view draws no path (it says why instead)
        // The view's plane -> widget mapping (one scale, an offset): three points give it.
        const QPointF origin = m_view->toWidget(QPointF(0, 0));
        const QPointF right = m_view->toWidget(QPointF(1, 0)) - origin;
        const QPointF up = m_view->toWidget(QPointF(0, 1)) - origin;
        const QTransform toWidget(right.x(), right.y(), up.x(), up.y(), origin.x(), origin.y());
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setBrush(Qt::NoBrush);
        if (!segments.isEmpty()) {
            // Cosmetic and 1 px, as the view's own pens (the raster engine's fast stroker),
            // over the view's line.
            QPen pen(errorColor(), 1);
            pen.setCosmetic(true);
            painter.save();
            painter.setTransform(toWidget);
            painter.setPen(pen);
            painter.drawPath(segments);
            painter.restore();
        }
        painter.setPen(QPen(errorColor(), 2));
        for (const QPointF& ring : rings)
            painter.drawEllipse(toWidget.map(ring), 5, 5);
        paintLegend(painter);
    }

private:
    // The view draws the points known on its axes, in path order (PreviewScene::project): the
    // axes (bits 0 X, 1 Y, 2 Z) whose points are exactly the drawn ones, line by line.
    std::optional<unsigned> drawnAxes(const PreviewScene::Projected& drawn) const
    {
        for (unsigned axes : {0b011u, 0b101u, 0b110u, 0b111u}) {
            qsizetype j = 0;
            bool same = true;
            for (qsizetype i = 0; i < m_known.size() && same; ++i)
                if ((m_known.at(i) & axes) == axes) {
                    same = j < drawn.lines.size() && drawn.lines.at(j) == m_lines.at(i);
                    ++j;
                }
            if (same && j == drawn.points.size())
                return axes;
        }
        return std::nullopt;
    }

    // The segments to and from points beyond the limits, and where the path leaves them, in
    // the view's plane; false: nothing to draw.
    bool inPlane(QPainterPath* segments, QList<QPointF>* rings) const
    {
        const PreviewScene::Projected& drawn = m_view->projected();
        if (m_count == 0 || drawn.points.isEmpty() || m_beyond.size() != m_known.size())
            return false;
        const std::optional<unsigned> axes = drawnAxes(drawn);
        if (!axes)
            return false; // not the path this view draws
        qsizetype j = -1;
        bool previousDrawn = false;
        bool previousBeyond = false;
        for (qsizetype i = 0; i < m_known.size(); ++i) {
            if ((m_known.at(i) & *axes) != *axes) { // not drawn: the path breaks there
                previousDrawn = false;
                previousBeyond = false;
                continue;
            }
            ++j;
            const QPointF at = drawn.points.at(j);
            const bool outside = m_beyond.at(i);
            if (previousDrawn && (outside || previousBeyond)) {
                const QPointF from = drawn.points.at(j - 1);
                if (segments->elementCount() == 0 || segments->currentPosition() != from)
                    segments->moveTo(from);
                segments->lineTo(at);
            }
            if (outside && !previousBeyond && rings->size() < kMaxLimitExits)
                *rings << at;
            previousDrawn = true;
            previousBeyond = outside;
        }
        return true;
    }

    void paintLegend(QPainter& painter) const
    {
        constexpr int kSample = 22;
        const QFontMetrics metrics(font());
        const int left = m_view->fitButton()->geometry().right() + 8;
        const int right = width() - 6;
        const int room = right - left - kSample - 12;
        if (room < 40 || m_legend.isEmpty())
            return;
        const QString text = metrics.elidedText(m_legend, Qt::ElideRight, room);
        const int textWidth = metrics.horizontalAdvance(text);
        const int top = 4;
        const QRect box(right - textWidth - kSample - 12, top - 2, textWidth + kSample + 12,
                        metrics.height() + 4);
        QColor backdrop = palette().color(QPalette::Base);
        backdrop.setAlpha(210);
        painter.fillRect(box, backdrop);
        const double mid = top + metrics.height() / 2.0;
        painter.setPen(QPen(errorColor(), 2));
        painter.drawLine(QPointF(box.left() + 4, mid), QPointF(box.left() + 4 + kSample, mid));
        painter.setPen(palette().color(QPalette::Text));
        painter.drawText(QRect(box.left() + kSample + 8, top, textWidth + 1, metrics.height()),
                         Qt::AlignLeft | Qt::AlignVCenter, text);
    }

    ProgramPathView* m_view;
    // Per point of the preview's path: its known axes among X, Y, Z (bits), its line, and
    // whether it lies beyond the soft limits.
    QList<unsigned> m_known;
    QList<int> m_lines;
    QList<bool> m_beyond;
    QString m_legend;
    int m_count = 0; // points beyond
};

ProgramPreviewView::ProgramPreviewView(QWidget* parent)
    : QWidget(parent), m_path(new ProgramPathView(this)),
      m_limits(new PreviewLimitsOverlay(m_path)), m_chart(new QChart),
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
    m_hasPreview = false;
    m_showsErrors = false;
    m_limits->clear();
    m_path->clearPath(reason);
    clearChart();
    m_extents->setRowCount(0);
    m_figures->setText(reason);
    m_motionNote->clear();
    m_coordinates->clear();
    m_figures->setToolTip(QString());
    updateErrorsTab();
}

void ProgramPreviewView::setErrorList(QWidget* list)
{
    if (m_errorsTab >= 0 || !list)
        return;
    m_errorsTab = m_tabs->addTab(list, tr("Errors"));
    updateErrorsTab();
}

void ProgramPreviewView::setErrorCount(int count)
{
    m_errorCount = count;
    updateErrorsTab();
}

// Nothing moves when errors come and go: only which tab can be chosen, and which is shown.
void ProgramPreviewView::updateErrorsTab()
{
    if (m_errorsTab < 0)
        return;
    const bool any = m_errorCount > 0;
    const bool listOnly = any && !m_hasPreview; // no path (it does not parse): the list alone
    m_tabs->setTabText(m_errorsTab, any ? tr("Errors (%1)").arg(m_errorCount) : tr("Errors"));
    m_tabs->tabBar()->setTabTextColor(m_errorsTab, any ? kErrorText : QColor());
    m_tabs->setTabToolTip(m_errorsTab,
                          any ? tr("The check's errors: Run stays off until there are none.")
                              : tr("The check found no errors."));
    // Enabled, then shown, then the others disabled: a tab disabled while it is shown hands
    // the view to another.
    if (any)
        m_tabs->setTabEnabled(m_errorsTab, true);
    if (!listOnly)
        for (int i = 0; i < m_tabs->count(); ++i)
            if (i != m_errorsTab)
                m_tabs->setTabEnabled(i, true);
    if (listOnly && !m_errorsChosen) {
        m_tabBeforeErrors = m_tabs->currentIndex() == m_errorsTab ? 0 : m_tabs->currentIndex();
        m_errorsChosen = true;
        m_tabs->setCurrentIndex(m_errorsTab);
    } else if (!listOnly && m_errorsChosen) {
        // A path again: the tab the operator had, the path with the errors marked on it.
        m_errorsChosen = false;
        if (m_tabs->currentIndex() == m_errorsTab)
            m_tabs->setCurrentIndex(m_tabBeforeErrors);
    }
    if (!any && m_tabs->currentIndex() == m_errorsTab)
        m_tabs->setCurrentIndex(0);
    if (listOnly)
        for (int i = 0; i < m_tabs->count(); ++i)
            if (i != m_errorsTab)
                m_tabs->setTabEnabled(i, false);
    if (!any)
        m_tabs->setTabEnabled(m_errorsTab, false);
}

int ProgramPreviewView::pointsBeyondLimits() const
{
    return m_limits->count();
}

QList<QPointF> ProgramPreviewView::limitExits() const
{
    return m_limits->exits();
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
    m_hasPreview = true;
    m_showsErrors = preview.hasErrors;
    // A program with errors (issue 47 item 12): what lies beyond the soft limits marked.
    if (preview.hasErrors)
        m_limits->setPath(preview.path, beyondLimits(preview, machine),
                          tr("Beyond the soft limits"));
    else
        m_limits->clear();
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
    // The path as checked, not a plan: said first (Run stays off while there are errors).
    if (preview.hasErrors)
        figures = tr("Has errors, not runnable") + QStringLiteral(" \u00b7 ") + figures;
    m_figures->setText(figures);
    // Issue 50 item 4: how tools get their length (touch-off: the holds at M6) goes with how
    // the axes move together.
    QStringList notes;
    for (const QString& part : {preview.motionNote, preview.toolNote})
        if (!part.isEmpty())
            notes << part;
    const QString note = notes.join(QStringLiteral("; "));
    m_motionNote->setText(note);
    m_motionNote->setToolTip(note);
    m_figures->setToolTip(note);
    updateErrorsTab();
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
        // An end beyond the limits (a program with errors, issue 47 item 12) in the error
        // colour.
        if (work && beyond(axis, *work, it->minimum))
            m_extents->item(row, 1)->setForeground(kErrorText);
        if (work && beyond(axis, *work, it->maximum))
            m_extents->item(row, 2)->setForeground(kErrorText);
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
