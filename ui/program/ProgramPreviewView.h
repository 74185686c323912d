#pragma once
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include <QWidget>

class QChart;
class QChartView;
class QLineSeries;
class QTabWidget;
class QTableWidget;

namespace stepdeck::ui {

class ElidedLabel;
class PreviewLimitsOverlay;
class ProgramPathView;

// The preview of a checked program beside the editor (issue 20), in tabs: the path to scale
// from the top, front, side or isometric (ProgramPathView, issue 29), the axes besides X and Y
// over the estimated time (a chart), each moved axis' extent against its soft limits; above
// them, in summary() which the page places, the figures: lines, blocks run, the estimated
// duration and how the axes of a block move together; below them the coordinates (work
// coordinates, as the position display and the program's targets: issue 28, item 3).
// While a program runs the current position is drawn in both, and the running line's segments
// in the path.
// A program with errors (issue 47 item 12) keeps the path its check walked, marked as not
// runnable, with what lies beyond the soft limits in the error colour; the list of the errors
// (the page's, setErrorList()) is the last tab, so nothing moves or grows when errors come and
// go. A program without a path (it does not parse) has that tab alone.
class ProgramPreviewView : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPreviewView(QWidget* parent = nullptr);

    // A checked program's figures; with preview.hasErrors the path as the check walked it.
    void setPreview(const program::ProgramPreview& preview,
                    const machine::MachineDescription& machine);
    // No preview (a program that does not parse, no machine): the reason in place of the
    // figures.
    void clear(const QString& reason);
    // The check's list of errors (ProgramErrorList) as the last tab, "Errors (n)".
    void setErrorList(QWidget* list);
    // How many errors the list holds: none leaves its tab disabled; errors without a preview
    // (clear()) leave it the one tab to choose, chosen; errors with a preview keep the tab
    // the operator looks at (the path).
    void setErrorCount(int count);
    // The preview shown is of a program with errors (not runnable).
    bool showsErrors() const { return m_showsErrors; }
    int errorsTabIndex() const { return m_errorsTab; }
    // The shown path's points beyond the soft limits, and where it leaves them (in the view's
    // plane, as ProgramPathView::points()): marked in the error colour.
    int pointsBeyondLimits() const;
    QList<QPointF> limitExits() const;
    // While running: the machine axes' positions now (axes not known left out) and the
    // estimated time reached.
    void setCurrent(const QMap<QString, double>& positions, double seconds);
    // While running: the block that runs now (its segments highlighted in the path).
    void setRunningLine(int line);
    void clearCurrent();

    ProgramPathView* pathView() const { return m_path; }
    QChartView* chartView() const { return m_chartView; }
    QTableWidget* extentsTable() const { return m_extents; }
    QTabWidget* tabs() const { return m_tabs; }
    // The figures and the coordinates, one line each, for the page to place (issue 31: beside
    // the controls, so the path gets the preview's whole height).
    QWidget* summary() const { return m_summary; }
    QString figuresText() const;
    // Which coordinates the preview shows: work coordinates, each work zero's machine position.
    QString coordinatesText() const;
    QStringList chartedAxes() const;

private:
    void clearChart();
    void fillChart(const program::ProgramPreview& preview,
                   const machine::MachineDescription& machine);
    void fillExtents(const program::ProgramPreview& preview,
                     const machine::MachineDescription& machine);
    void updateErrorsTab();

    ProgramPathView* m_path;
    PreviewLimitsOverlay* m_limits; // over m_path
    QChart* m_chart;
    QChartView* m_chartView;
    QLineSeries* m_now = nullptr; // the vertical line at the time reached
    QTableWidget* m_extents;
    QTabWidget* m_tabs;
    QWidget* m_summary;
    ElidedLabel* m_figures;
    ElidedLabel* m_motionNote;
    ElidedLabel* m_coordinates;
    bool m_hasX = false;
    bool m_hasY = false;
    double m_chartMin = 0;
    double m_chartMax = 1;
    int m_errorsTab = -1;        // the errors' tab, once setErrorList() gave the list
    int m_errorCount = 0;        // setErrorCount()
    bool m_hasPreview = false;   // setPreview() since the last clear()
    bool m_showsErrors = false;  // that preview is of a program with errors
    bool m_errorsChosen = false; // the errors' tab was chosen for the operator (no path)
    int m_tabBeforeErrors = 0;   // the tab shown before it was
};

} // namespace stepdeck::ui
