// Charts: samples follow the status, the time window limits what is shown, pause freezes
// it, and the visible data exports to CSV and the charts to PNG.
#include "MachineTestSupport.h"
#include "TestMain.h"
#include "UiTestSupport.h"
#include "charts/ChartsPanel.h"
#include "machine/Machine.h"
#include "machine/MachineBar.h"
#include "setup/SetupPage.h"
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QImage>
#include <QLineSeries>
#include <QPushButton>
#include <QTemporaryDir>
#include <QValueAxis>

using namespace stepdeck;
using namespace stepdeck::test;

class TestChartsPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void sampler_window_keepsNewestSeconds();
    void sampler_csv_headerAndRows();
    void panel_followsStatus_exportsCsvAndPng();
    void charts_machineInMm_plotsEachAxisInItsUnit();
};

namespace {
// The chart of that title on the panel.
QChart* chartTitled(ui::ChartsPanel* panel, const QString& title)
{
    for (QChartView* view : panel->findChildren<QChartView*>()) {
        if (view->chart()->title() == title)
            return view->chart();
    }
    return nullptr;
}

QString valueAxisTitle(QChart* chart)
{
    const QList<QAbstractAxis*> axes = chart->axes(Qt::Vertical);
    return axes.isEmpty() ? QString() : axes.first()->titleText();
}

// The newest point of the series of that name (NaN: none).
double lastValue(QChart* chart, const QString& series)
{
    for (QAbstractSeries* s : chart->series()) {
        auto* line = qobject_cast<QLineSeries*>(s);
        if (line && line->name() == series && line->count() > 0)
            return line->at(line->count() - 1).y();
    }
    return qQNaN();
}
} // namespace

void TestChartsPanel::sampler_window_keepsNewestSeconds()
{
    ui::ChartSampler sampler;
    sampler.setInterval(0);
    MachineStatus s;
    s.axes.insert(Axis::X, AxisStatus{});
    for (int i = 0; i < 5; ++i)
        sampler.add(s, 20.0);
    QCOMPARE(sampler.samples().size(), 5);
    QVERIFY(sampler.window(3600).size() == 5);
    QVERIFY(sampler.window(-1).isEmpty());
}

void TestChartsPanel::sampler_csv_headerAndRows()
{
    ui::ChartSample a;
    a.t = 1.5;
    a.position = {{Axis::X, 10}, {Axis::Y, -20}};
    a.velocity = {{Axis::X, 100}, {Axis::Y, 0}};
    a.temperature = 31;
    a.pollRate = 19.5;
    // X a machine's axis in mm (400 steps/mm), Y a controller's own axis in steps: each in
    // what the charts plot it in (issue 31).
    ui::ChartAxis x;
    x.axis = Axis::X;
    x.name = QStringLiteral("X");
    machine::MachineAxis mm;
    mm.name = QStringLiteral("X");
    mm.unit = machine::AxisUnit::Millimetre;
    mm.stepsPerUnit = 400;
    x.inMachine = mm;
    ui::ChartAxis y;
    y.axis = Axis::Y;
    y.name = QStringLiteral("Y");
    const QString csv = ui::ChartSampler::toCsv({a}, {x, y});
    const QStringList lines = csv.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    QCOMPARE(lines[0], QStringLiteral("time_s,position_X_mm,position_Y_steps,"
                                      "velocity_X_mm_per_s,velocity_Y_steps_per_s,"
                                      "temperature_c,poll_rate_hz"));
    QCOMPARE(lines[1], QStringLiteral("1.500,0.0250,-20,0.250,0.0,31.0,19.5"));
}

void TestChartsPanel::panel_followsStatus_exportsCsvAndPng()
{
    QSettings().clear();
    UiFixture f;
    f.window->show();
    QVERIFY(f.connectSim());
    ui::ChartsPanel* charts = f.window->chartsPanel();
    QTRY_VERIFY_WITH_TIMEOUT(charts->sampler()->samples().size() >= 5, 5000);
    f.window->raisePage(charts);
    QTRY_VERIFY_WITH_TIMEOUT(charts->pointCount(0) >= 5, 3000);
    // Behind another tab the charts are not redrawn (idle cost), the samples still collect,
    // and showing the panel brings it up to date at once.
    f.window->raisePage(f.window->setupPage());
    const int hidden = charts->pointCount(0);
    const int before = f.statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(f.statusCount - before >= 10, 3000);
    QCOMPARE(charts->pointCount(0), hidden);
    f.window->raisePage(charts);
    QTRY_VERIFY(charts->pointCount(0) > hidden);
    charts->pauseCheck()->setChecked(true);
    const int frozen = charts->pointCount(0);
    const int from = f.statusCount;
    QTRY_VERIFY_WITH_TIMEOUT(f.statusCount - from >= 10, 3000);
    charts->refresh();
    QCOMPARE(charts->pointCount(0), frozen);

    QTemporaryDir dir;
    QString error;
    const QString csv = dir.filePath(QStringLiteral("c.csv"));
    QVERIFY2(charts->exportCsv(csv, &error), qPrintable(error));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll().count('\n'), frozen + 1); // header + the visible samples
    const QString png = dir.filePath(QStringLiteral("c.png"));
    QVERIFY2(charts->exportPng(png, &error), qPrintable(error));
    QVERIFY(!QImage(png).isNull());
}

// Issue 31: "the charts show a machine in mm in steps". A bare controller is plotted in steps;
// a machine in mm is plotted in mm (its axes' names and units, the unit in the value axis'
// title), the way the Position read-out converts: a move of 2.5 mm is 2.5, not 1000 steps.
void TestChartsPanel::charts_machineInMm_plotsEachAxisInItsUnit()
{
    QSettings().clear();
    UiFixture f;
    f.window->show();
    ui::ChartsPanel* charts = f.window->chartsPanel();
    f.window->raisePage(charts);
    QCOMPARE(valueAxisTitle(chartTitled(charts, QStringLiteral("Position"))),
             QStringLiteral("steps"));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mm.machine.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({
  "format": "stepdeck-machine", "version": 1, "name": "Table in mm",
  "controllers": [ { "id": "table", "model": "elab", "port": "sim" } ],
  "axes": [
    { "name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400 },
    { "name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800 }
  ]
})");
    file.close();
    QVERIFY(f.window->openMachine(path));
    f.window->machineBar()->connectButton()->click();
    machine::Machine* m = f.window->context()->machine();
    ControllerSession* table = m->session(QStringLiteral("table"));
    QTRY_VERIFY_WITH_TIMEOUT(table->linkState() == LinkState::Connected, 10000);
    QVERIFY(writeSetupBeforeMotion(table));

    QChart* position = chartTitled(charts, QStringLiteral("Position"));
    QVERIFY(position);
    QCOMPARE(valueAxisTitle(position), QStringLiteral("mm"));
    QCOMPARE(valueAxisTitle(chartTitled(charts, QStringLiteral("Commanded velocity"))),
             QStringLiteral("mm/s"));
    QString refusal;
    QVERIFY2(m->move({{QStringLiteral("X"), 2.5}}, false, &refusal), qPrintable(refusal));
    QTRY_VERIFY_WITH_TIMEOUT(table->status().axes.value(Axis::X).position == 1000 &&
                                 !table->status().anyMoving(),
                             10000);
    QTRY_COMPARE_WITH_TIMEOUT(lastValue(position, QStringLiteral("X")), 2.5, 5000);
    QCOMPARE(lastValue(position, QStringLiteral("Y")), 0.0);
    // The CSV export as the charts plot it: in mm, the header saying so.
    QString error;
    const QString csv = dir.filePath(QStringLiteral("mm.csv"));
    QVERIFY2(charts->exportCsv(csv, &error), qPrintable(error));
    QFile exported(csv);
    QVERIFY(exported.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(exported.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(lines.size() >= 2);
    const QStringList header = lines.first().split(QLatin1Char(','));
    const int column = int(header.indexOf(QStringLiteral("position_X_mm")));
    QVERIFY2(column > 0, qPrintable(lines.first()));
    QVERIFY(header.contains(QStringLiteral("velocity_Z_mm_per_s")));
    QCOMPARE(lines.last().split(QLatin1Char(',')).value(column), QStringLiteral("2.5000"));
}

STEPDECK_TEST_MAIN(TestChartsPanel)
#include "tst_chartspanel.moc"
