// A controller axis is an index with a default name (issue 32, step 2): X, Y, Z, U for the
// first four, axis5 ... axis254 after them, each name back to its axis and nothing else.
#include "TestMain.h"
#include "model/Axis.h"
#include <QtTest>

using namespace stepdeck;

class TestAxis : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void fromIndex_insideRange_keepsIndex_data();
    void fromIndex_insideRange_keepsIndex();
    void fromIndex_outsideRange_isNone();
    void axisName_roundTrips_data();
    void axisName_roundTrips();
    void axisFromName_notADefaultName_isNone_data();
    void axisFromName_notADefaultName_isNone();
    void familiarSpellings_areTheFirstFourIndices();
    void order_isTheIndexOrder();
};

void TestAxis::fromIndex_insideRange_keepsIndex_data()
{
    QTest::addColumn<int>("index");
    for (int i : {0, 1, 3, 4, 100, Axis::kMaxCount - 1})
        QTest::addRow("%d", i) << i;
}

void TestAxis::fromIndex_insideRange_keepsIndex()
{
    QFETCH(int, index);
    const std::optional<Axis> axis = Axis::fromIndex(index);
    QVERIFY(axis.has_value());
    QCOMPARE(axis->index(), index);
    QCOMPARE(Axis::at(index), *axis);
}

void TestAxis::fromIndex_outsideRange_isNone()
{
    QVERIFY(!Axis::fromIndex(-1));
    QVERIFY(!Axis::fromIndex(Axis::kMaxCount));
    QVERIFY(!Axis::fromIndex(100000));
    QCOMPARE(Axis::kMaxCount, 254); // a Nanotec bus: addresses 1..254 (1.1)
}

void TestAxis::axisName_roundTrips_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<QString>("name");
    QTest::newRow("X") << 0 << "X";
    QTest::newRow("Y") << 1 << "Y";
    QTest::newRow("Z") << 2 << "Z";
    QTest::newRow("U") << 3 << "U";
    QTest::newRow("fifth") << 4 << "axis5";
    QTest::newRow("tenth") << 9 << "axis10";
    QTest::newRow("last") << 253 << "axis254";
}

void TestAxis::axisName_roundTrips()
{
    QFETCH(int, index);
    QFETCH(QString, name);
    QCOMPARE(axisName(Axis::at(index)), name);
    QCOMPARE(axisFromName(name), Axis::fromIndex(index));
    QCOMPARE(axisFromName(name.toLower()), Axis::fromIndex(index));
    QCOMPARE(axisFromName(QStringLiteral(" %1 ").arg(name.toUpper())), Axis::fromIndex(index));
}

void TestAxis::axisFromName_notADefaultName_isNone_data()
{
    QTest::addColumn<QString>("name");
    for (const char* name : {"", "A", "Q", "XY", "axis", "axis0", "axis1", "axis4", "axis05",
                             "axis+5", "axis-5", "axis 5", "axis255", "axis5x", "feeder", "5"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestAxis::axisFromName_notADefaultName_isNone()
{
    QFETCH(QString, name);
    QCOMPARE(axisFromName(name), std::nullopt);
}

void TestAxis::familiarSpellings_areTheFirstFourIndices()
{
    QCOMPARE(Axis::X.index(), 0);
    QCOMPARE(Axis::Y.index(), 1);
    QCOMPARE(Axis::Z.index(), 2);
    QCOMPARE(Axis::U.index(), 3);
    QCOMPARE(letterAxes(), (QList<Axis>{Axis::X, Axis::Y, Axis::Z, Axis::U}));
    QCOMPARE(Axis(), Axis::X);
}

void TestAxis::order_isTheIndexOrder()
{
    const AxisVector v{{Axis::at(200), 3}, {Axis::Y, 2}, {Axis::at(4), 1}};
    QCOMPARE(v.keys(), (QList<Axis>{Axis::Y, Axis::at(4), Axis::at(200)}));
    QVERIFY(Axis::X < Axis::Y);
    QVERIFY(Axis::at(10) > Axis::U);
    QVERIFY(qHash(Axis::X) != qHash(Axis::Y));
}

STEPDECK_TEST_GUILESS_MAIN(TestAxis)
#include "tst_axis.moc"
