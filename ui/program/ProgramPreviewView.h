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
class ProgramPathView;

// The preview of a checked program beside the editor (issue 20), in tabs: the path to scale
// from the top, front, side or isometric (ProgramPathView, issue 29), the axes besides X and Y
// over the estimated time (a chart), each moved axis' extent against its soft limits; above
// them, in summary() which the page places, the figures: lines, blocks run, the estimated
// duration and how the axes of a block move together; below them the coordinates (work
// coordinates, as the position display and the program's targets: issue 28, item 3).
// While a program runs the current position is drawn in both, and the running line's segments
// in the path.
class ProgramPreviewView : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPreviewView(QWidget* parent = nullptr);

    void setPreview(const program::ProgramPreview& preview,
                    const machine::MachineDescription& machine);
    // No preview (a program with errors, no machine): the reason in place of the figures.
    void clear(const QString& reason);
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

    ProgramPathView* m_path;
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
};

} // namespace stepdeck::ui
