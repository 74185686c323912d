// G2/G3 in a machine's terms (ArcPath, issue 29, docs/programs.md "Arcs"): the centre by I J K
// and R as LinuxCNC computes it, the direction in each plane, full circles, helices with turns,
// LinuxCNC's end-point tolerance (a spiral within it, an error naming the radii beyond it),
// work offsets and inches, the chords within the tolerance of the true curve, and the bounds
// the soft limits are checked at.
#include "MillTestSupport.h"
#include "TestMain.h"
#include "program/ArcPath.h"
#include "program/ProgramParser.h"
#include <QtTest>
#include <cmath>

using namespace stepdeck;
using namespace stepdeck::program;

namespace {

using pathtest::mill;

// The last block of `program` (parsed for X Y Z).
ProgramBlock lastBlock(const QString& program)
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(
        program.toUtf8(), {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}, &errors);
    if (!p || p->allBlocks().isEmpty()) {
        qWarning() << (errors.isEmpty() ? QString() : errors.first().text());
        return {};
    }
    return p->allBlocks().last();
}

QString errorOf(const std::variant<ArcPath, ArcPath::Error>& planned)
{
    const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planned);
    return e ? e->message : QString();
}

AxisPositions at(double x, double y, double z)
{
    return {x, y, z};
}

QString pointText(const QList<std::pair<int, double>>& point)
{
    QStringList out;
    const char* names[] = {"X", "Y", "Z"};
    for (const auto& [axis, value] : point)
        out << QStringLiteral("%1%2").arg(QLatin1String(names[axis])).arg(value, 0, 'f', 3);
    return out.join(QLatin1Char(' '));
}

QString boundsText(const ArcPath& path)
{
    QStringList out;
    const char* names[] = {"X", "Y", "Z"};
    for (const auto& [axis, range] : path.bounds())
        out << QStringLiteral("%1[%2,%3]")
                   .arg(QLatin1String(names[axis]))
                   .arg(range.first, 0, 'f', 3)
                   .arg(range.second, 0, 'f', 3);
    return out.join(QLatin1Char(' '));
}

} // namespace

class TestArcPath : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void plan_arcs_endMiddleAndBounds_data();
    void plan_arcs_endMiddleAndBounds();
    void plan_refused_columnAndMessage_data();
    void plan_refused_columnAndMessage();
    void chords_fullCircle_withinToleranceOfTheCircle();
    void chords_spiralWithinTolerance_endsExactlyAtTheEndPoint();
    void helix_turns_helixAxisMovesWithTheAngle();
    void workOffsets_absoluteEndAndCentre_inMachineCoordinates();
    void rateBlock_arcAxes_asAG1();
};

void TestArcPath::plan_arcs_endMiddleAndBounds_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<double>("sweepDegrees");
    QTest::addColumn<QPointF>("centre"); // in the plane's axes, LinuxCNC's order (G18: Z, X)
    QTest::addColumn<QString>("bounds");
    // From X0 Y0 Z0 in each case.
    QTest::newRow("G3 half circle passes +X")
        << "G3 X0 Y10 I0 J5 F100" << 180.0 << QPointF(0, 5) << "X[0.000,5.000] Y[0.000,10.000]";
    QTest::newRow("G2 half circle passes -X")
        << "G2 X0 Y10 I0 J5 F100" << -180.0 << QPointF(0, 5) << "X[-5.000,0.000] Y[0.000,10.000]";
    QTest::newRow("G2 R+ takes the shorter arc")
        << "G2 X10 Y0 R10 F100" << -60.0 << QPointF(5, -8.660254)
        << "X[0.000,10.000] Y[0.000,1.340]";
    QTest::newRow("G2 R- takes the longer arc")
        << "G2 X10 Y0 R-10 F100" << -300.0 << QPointF(5, 8.660254)
        << "X[-5.000,15.000] Y[0.000,18.660]";
    QTest::newRow("G3 R+ shorter, the other side")
        << "G3 X10 Y0 R10 F100" << 60.0 << QPointF(5, 8.660254)
        << "X[0.000,10.000] Y[-1.340,0.000]";
    QTest::newRow("full circle G2 I5")
        << "G2 I5 F100" << -360.0 << QPointF(5, 0) << "X[0.000,10.000] Y[-5.000,5.000]";
    QTest::newRow("full circle G3 J-4")
        << "G3 J-4 F100" << 360.0 << QPointF(0, -4) << "X[-4.000,4.000] Y[-8.000,0.000]";
    // LinuxCNC's G18 turns from Z towards X: G2 is clockwise seen from +Y.
    QTest::newRow("G18 G2 passes -Z") << "G18 G2 X10 Z0 I5 K0 F100" << -180.0 << QPointF(0, 5)
                                      << "Z[-5.000,0.000] X[0.000,10.000]";
    QTest::newRow("G19 G3 passes +Y")
        << "G19 G3 Y0 Z10 J0 K5 F100" << 180.0 << QPointF(0, 5) << "Y[0.000,5.000] Z[0.000,10.000]";
    QTest::newRow("G91 end and centre relative")
        << "G91 G2 X10 Y10 I10 J0 F100" << -90.0 << QPointF(10, 0)
        << "X[0.000,10.000] Y[0.000,10.000]";
    QTest::newRow("G20: inches on mm axes")
        << "G20 G3 X0 Y1 I0 J0.5 F4" << 180.0 << QPointF(0, 12.7)
        << "X[0.000,12.700] Y[0.000,25.400]";
    QTest::newRow("two turns") << "G3 X0 Y10 J5 P2 F100" << 540.0 << QPointF(0, 5)
                               << "X[-5.000,5.000] Y[0.000,10.000]";
}

void TestArcPath::plan_arcs_endMiddleAndBounds()
{
    QFETCH(QString, program);
    QFETCH(double, sweepDegrees);
    QFETCH(QPointF, centre);
    QFETCH(QString, bounds);
    const ProgramBlock block = lastBlock(program);
    QVERIFY(isArc(block.kind));
    const auto planned = ArcPath::plan(block, mill(), at(0, 0, 0), {});
    const ArcPath* path = std::get_if<ArcPath>(&planned);
    QVERIFY2(path, qPrintable(errorOf(planned)));
    QCOMPARE(qRound(path->sweep() * 180 / M_PI * 1000) / 1000.0, sweepDegrees);
    // Every chord's end lies on the circle about the centre, and they turn the arc's way.
    double turned = 0;
    double previous = 0;
    for (qint64 k = 1; k <= path->chords(); ++k) {
        const QList<std::pair<int, double>> p = path->pointAt(k);
        const double u = p.at(0).second - centre.x(), v = p.at(1).second - centre.y();
        QVERIFY2(std::abs(std::hypot(u, v) - path->radius()) < 1e-5, qPrintable(pointText(p)));
        const double angle = std::atan2(v, u);
        if (k > 1)
            turned += std::remainder(angle - previous, 2 * M_PI);
        previous = angle;
    }
    const double perChord = path->sweep() / double(path->chords());
    QCOMPARE(qRound((turned + perChord) * 180 / M_PI), qRound(sweepDegrees));
    QCOMPARE(boundsText(*path), bounds);
}

void TestArcPath::plan_refused_columnAndMessage_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message");
    QTest::newRow("end off the circle")
        << "G2 X10 Y0 I4 J0 F100" << 1
        << "G2: the end point is not on the arc: radius 4 at the start, 6 at the end, 2 apart (at "
           "most 0.028 allowed): check the centre and the end point";
    QTest::newRow("end off the circle, inches")
        << "G20 G2 X1 Y0 I0.4 J0 F10" << 5
        << "G2: the end point is not on the arc: radius 0.4 at the start, 0.6 at the end, 0.2 "
           "apart (at most 0.003 allowed): check the centre and the end point";
    QTest::newRow("R too short") << "G2 X10 Y0 R4 F100" << 11
                                 << "G2: R4 is too short to reach the end point, 10 away";
    QTest::newRow("R with the end at the start")
        << "G3 X0 Y0 R4 F100" << 10
        << "G3 with R: the end point is the start point; a full circle takes I, J or K";
    QTest::newRow("huge radius") << "G2 X0 Y0 I9999999999 J0 F100" << 1
                                 << "G2: the arc's radius is larger than 1000000000";
    QTest::newRow("too many chords")
        << "G2 X0 Y0 I99999999 J0 P1000 F100" << 1 << "G2: the arc needs more than 1000000 chords";
    QTest::newRow("centre on the start")
        << "G2 X10 Y0 I0 J0 F100" << 1 << "G2: the centre lies on the start or the end point";
}

void TestArcPath::plan_refused_columnAndMessage()
{
    QFETCH(QString, program);
    QFETCH(int, column);
    QFETCH(QString, message);
    const ProgramBlock block = lastBlock(program);
    QVERIFY(isArc(block.kind));
    const auto planned = ArcPath::plan(block, mill(), at(0, 0, 0), {});
    const ArcPath::Error* e = std::get_if<ArcPath::Error>(&planned);
    QVERIFY(e);
    QCOMPARE(e->message, message);
    QCOMPARE(e->column, column);
}

void TestArcPath::chords_fullCircle_withinToleranceOfTheCircle()
{
    const ProgramBlock block = lastBlock("G2 I25 F100");
    const auto planned = ArcPath::plan(block, mill(), at(0, 0, 0), {});
    const ArcPath& path = std::get<ArcPath>(planned);
    QVERIFY(path.chords() >= 4);
    double previous[2] = {0, 0};
    double worst = 0;
    for (qint64 k = 1; k <= path.chords(); ++k) {
        const QList<std::pair<int, double>> p = path.pointAt(k);
        const double x = p.at(0).second, y = p.at(1).second;
        QVERIFY(std::abs(std::hypot(x - 25, y) - 25) < 1e-9); // every chord end is on the circle
        // The chord's middle is closest to the centre: its distance to the circle is the error.
        const double mx = (x + previous[0]) / 2, my = (y + previous[1]) / 2;
        worst = std::max(worst, 25 - std::hypot(mx - 25, my));
        previous[0] = x;
        previous[1] = y;
    }
    QVERIFY2(worst <= ArcPath::chordTolerance(mill().axes.first()) + 1e-12,
             qPrintable(QString::number(worst)));
    QVERIFY(worst > 0.005); // not many more chords than the tolerance needs
    QCOMPARE(pointText(path.pointAt(path.chords())), QStringLiteral("X0.000 Y0.000"));
}

void TestArcPath::chords_spiralWithinTolerance_endsExactlyAtTheEndPoint()
{
    // Radii 5.01 and 4.99 differ by 0.02, within LinuxCNC's 0.028: a spiral that ends exactly.
    const ProgramBlock block = lastBlock("G2 X10 Y0 I5.01 J0 F100");
    const auto planned = ArcPath::plan(block, mill(), at(0, 0, 0), {});
    const ArcPath* path = std::get_if<ArcPath>(&planned);
    QVERIFY(path);
    const QList<std::pair<int, double>> end = path->end();
    QCOMPARE(end.at(0).second, 10.0);
    QCOMPARE(end.at(1).second, 0.0);
    QCOMPARE(path->radius(), 5.01);
}

void TestArcPath::helix_turns_helixAxisMovesWithTheAngle()
{
    const ProgramBlock block = lastBlock("G91 G3 Z-3 I5 P3 F100");
    const auto planned = ArcPath::plan(block, mill(), at(0, 0, 1), {});
    const ArcPath& path = std::get<ArcPath>(planned);
    QCOMPARE(qRound(path.sweep() * 180 / M_PI), 3 * 360);
    // Z falls in proportion to the angle turned: 1 mm a turn.
    const qint64 n = path.chords();
    for (const qint64 k : {n / 7, n / 3, n / 2, n - 1}) {
        const QList<std::pair<int, double>> p = path.pointAt(k);
        QCOMPARE(p.size(), 3);
        QVERIFY(std::abs(p.at(2).second - (1 - 3.0 * double(k) / double(n))) < 1e-12);
    }
    QCOMPARE(pointText(path.end()), QStringLiteral("X0.000 Y0.000 Z-2.000"));
    QCOMPARE(ArcPath::movingAxes(block), (QStringList{"X", "Y", "Z"}));
}

void TestArcPath::workOffsets_absoluteEndAndCentre_inMachineCoordinates()
{
    // Work zero at machine X100 Y50: the program's X10 Y0 is machine X110 Y50.
    const QMap<QString, double> offsets{{"X", 100.0}, {"Y", 50.0}};
    const ProgramBlock block = lastBlock("G90.1 G2 X10 Y0 I5 J0 F100");
    const auto planned = ArcPath::plan(block, mill(), at(100, 50, 0), offsets);
    const ArcPath* path = std::get_if<ArcPath>(&planned);
    QVERIFY2(path, qPrintable(errorOf(planned)));
    QCOMPARE(pointText(path->end()), QStringLiteral("X110.000 Y50.000"));
    QCOMPARE(boundsText(*path), QStringLiteral("X[100.000,110.000] Y[50.000,55.000]"));
}

void TestArcPath::rateBlock_arcAxes_asAG1()
{
    const ProgramBlock block = lastBlock("G18 G2 X10 I5 F100");
    const ProgramBlock rates = ArcPath::rateBlock(block);
    QCOMPARE(rates.kind, BlockKind::Feed);
    QCOMPARE(rates.axes.keys(), (QStringList{"X", "Z"}));
    QCOMPARE(rates.feed, std::optional<double>(100));
    QCOMPARE(rates.line, block.line);
}

STEPDECK_TEST_APPLESS_MAIN(TestArcPath)
#include "tst_arcpath.moc"
