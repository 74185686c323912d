// A G94 G1 over several axes as LinuxCNC moves it (issue 30, CoordinatedFeed): on controllers
// that coordinate, each axis gets the share of F that its distance has of the path (measured
// over the linear axes; over the rotary ones when only they move), so all take length / F. The
// figures are worked out by hand.
#include "TestMain.h"
#include "machine/MachineDescription.h"
#include "program/CoordinatedFeed.h"
#include "program/ProgramParser.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;
using machine::AxisUnit;

namespace {

// "bench": a coordinating controller "table" with X Y (mm, 100 steps/mm) and A B (deg), and
// "other" with W Z (mm) that does not coordinate.
machine::MachineDescription bench()
{
    machine::MachineDescription d;
    for (const char* id : {"table", "other"}) {
        machine::MachineController c;
        c.id = QLatin1String(id);
        c.modelId = QStringLiteral("emis");
        d.controllers << c;
    }
    const auto axis = [](const char* name, const char* controller, Axis on, AxisUnit unit) {
        machine::MachineAxis a;
        a.name = QLatin1String(name);
        a.controller = QLatin1String(controller);
        a.axis = on;
        a.unit = unit;
        a.stepsPerUnit = 100;
        return a;
    };
    d.axes << axis("X", "table", Axis::X, AxisUnit::Millimetre)
           << axis("Y", "table", Axis::Y, AxisUnit::Millimetre)
           << axis("A", "table", Axis::Z, AxisUnit::Degree)
           << axis("B", "table", Axis::U, AxisUnit::Degree)
           << axis("W", "other", Axis::X, AxisUnit::Millimetre)
           << axis("Z", "other", Axis::Y, AxisUnit::Millimetre);
    return d;
}

const CoordinatedFeed::Controllers kTable{QStringLiteral("table")};

ProgramBlock lastParsedBlock(const QString& program)
{
    QList<ProgramError> errors;
    const std::optional<Program> p =
        ProgramParser::parse(program.toUtf8(), {"X", "Y", "A", "B", "W", "Z"}, &errors);
    if (!p || p->allBlocks().isEmpty()) {
        qWarning() << (errors.isEmpty() ? QString() : errors.first().text());
        return {};
    }
    return p->allBlocks().last();
}

// "X=180 Y=240": the rates, in each axis' unit per minute, rounded to 0.001.
QString ratesText(const ProgramBlock& block)
{
    QStringList out;
    for (auto it = block.axisRates.cbegin(); it != block.axisRates.cend(); ++it)
        out << QStringLiteral("%1=%2").arg(it.key()).arg(std::round(it.value() * 1000) / 1000);
    return out.join(QLatin1Char(' '));
}

} // namespace

class TestCoordinatedFeed : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void resolve_g1_sharesOfF_data();
    void resolve_g1_sharesOfF();
    void resolveChord_arc_sharesAlongEachChord();
    void resolve_feedOverride_scalesEveryShare();
};

void TestCoordinatedFeed::resolve_g1_sharesOfF_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("rates");
    // A 3-4-5 triangle at F300: 0.01 min; X 3 mm and Y 4 mm in it.
    QTest::newRow("diagonal: 3/5 and 4/5 of F") << "G1 X3 Y4 F300"
                                                << "X=180 Y=240";
    QTest::newRow("relative the same") << "G91 G1 X-3 Y4 F300"
                                       << "X=180 Y=240";
    QTest::newRow("one axis: F, no rates") << "G1 X3 F300"
                                           << "";
    QTest::newRow("from where the block starts (X=1 Y=1)") << "G1 X4 Y5 F300"
                                                           << "X=180 Y=240";
    // Linear and rotary: the length over X, Y (5 mm in 1/60 min), A's 30 deg in that time.
    QTest::newRow("rotary beside linear: its degrees in the linear time") << "G1 X3 Y4 A30 F300"
                                                                          << "A=1800 X=180 Y=240";
    QTest::newRow("rotary alone: F in deg/min") << "G1 A30 B40 F600"
                                                << "A=360 B=480";
    QTest::newRow("an axis that does not move: F, no rates") << "G1 X3 Y0 F300"
                                                             << "";
    // G20: F10 in/min is 254 mm/min along 5 mm.
    QTest::newRow("inches: F in inch/min over mm axes") << "G20 G1 X0.3 Y0.4 F10"
                                                        << "X=152.4 Y=203.2";
    QTest::newRow("inverse time is not resolved here") << "G93 G1 X3 Y4 F10"
                                                       << "";
    // W is on a controller that does not coordinate: it keeps F; the length counts it (LinuxCNC
    // measures the whole move), so X gets 3/sqrt(34) of F.
    QTest::newRow("another controller's axis keeps F") << "G1 X3 W5 F300"
                                                       << "X=154.349";
    QTest::newRow("no coordinating axis moves") << "G1 W3 Z1 F300"
                                                << "";
}

void TestCoordinatedFeed::resolve_g1_sharesOfF()
{
    QFETCH(QString, program);
    QFETCH(QString, rates);
    const machine::MachineDescription d = bench();
    AxisPositions start(size_t(d.axes.size()), 0.0);
    if (QTest::currentDataTag() == QByteArray("from where the block starts (X=1 Y=1)"))
        start[0] = start[1] = 1.0;
    const ProgramBlock block = lastParsedBlock(program);
    QCOMPARE(ratesText(CoordinatedFeed::resolve(block, d, kTable, start, {})), rates);
}

// A quarter circle of radius 10 from (10, 0) to (0, 10) around the origin, at F600: each
// chord's shares are |dx| and |dy| over the chord's length, times F, in the whole steps the
// device runs between the chord's rounded ends.
void TestCoordinatedFeed::resolveChord_arc_sharesAlongEachChord()
{
    const machine::MachineDescription d = bench();
    const ProgramBlock arc = lastParsedBlock(QStringLiteral("G3 X0 Y10 I-10 J0 F600"));
    AxisPositions start(size_t(d.axes.size()), 0.0);
    start[0] = 10.0;
    const auto planned = ArcPath::plan(arc, d, start, {});
    const ArcPath* path = std::get_if<ArcPath>(&planned);
    QVERIFY(path);
    QVERIFY(path->chords() > 10);
    for (qint64 k = 1; k <= path->chords(); ++k) {
        const ProgramBlock chord = CoordinatedFeed::resolveChord(arc, *path, k, d, kTable);
        double from[2] = {}, to[2] = {};
        for (const auto& [axis, value] : path->pointAt(k - 1))
            from[axis] = value;
        for (const auto& [axis, value] : path->pointAt(k))
            to[axis] = value;
        // The device runs whole steps: the chord's distances between its rounded ends.
        const double dx = std::abs(std::round(to[0] * 100) - std::round(from[0] * 100)) / 100;
        const double dy = std::abs(std::round(to[1] * 100) - std::round(from[1] * 100)) / 100;
        const double length = std::hypot(dx, dy);
        QVERIFY(length > 0);
        const double x = chord.axisRates.value(QStringLiteral("X"));
        const double y = chord.axisRates.value(QStringLiteral("Y"));
        QVERIFY2(std::abs(x - 600 * dx / length) < 1e-6, qPrintable(QString::number(k)));
        QVERIFY2(std::abs(y - 600 * dy / length) < 1e-6, qPrintable(QString::number(k)));
        // The path speed along the chord is F.
        QVERIFY(std::abs(std::hypot(x, y) - 600) < 1e-6);
    }
}

// The run's feed override (issue 30) times every share; other than 100 % a move of one axis
// gets its rate too (F times the override), so that it reaches the EMIS and Nanotec moves of
// their own.
void TestCoordinatedFeed::resolve_feedOverride_scalesEveryShare()
{
    const machine::MachineDescription d = bench();
    const AxisPositions start(size_t(d.axes.size()), 0.0);
    QCOMPARE(ratesText(CoordinatedFeed::resolve(lastParsedBlock("G1 X3 Y4 F300"), d, kTable, start,
                                                {}, 0.5)),
             QStringLiteral("X=90 Y=120"));
    QCOMPARE(
        ratesText(CoordinatedFeed::resolve(lastParsedBlock("G1 X3 F300"), d, kTable, start, {}, 2)),
        QStringLiteral("X=600"));
    QCOMPARE(
        ratesText(CoordinatedFeed::resolve(lastParsedBlock("G1 X3 F300"), d, kTable, start, {})),
        QString()); // at 100 %: F as it stands
    QCOMPARE(
        ratesText(CoordinatedFeed::resolve(lastParsedBlock("G1 W3 F300"), d, kTable, start, {}, 2)),
        QString()); // not a coordinating controller's
}

STEPDECK_TEST_GUILESS_MAIN(TestCoordinatedFeed)
#include "tst_coordinatedfeed.moc"
