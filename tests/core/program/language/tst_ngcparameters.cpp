// LinuxCNC's parameters as StepDeck keeps them (issue 33): numbered and named, a call's
// arguments, and the reserved ranges tied to the offsets or refused with the reason.
#include "TestMain.h"
#include "program/language/NgcParameters.h"
#include <QtTest>

using namespace stepdeck::program;

class TestNgcParameters : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void numbered_unset_readsZero();
    void numbered_reserved_tiedOrRefused_data();
    void numbered_reserved_tiedOrRefused();
    void setNumbered_reserved_refusedWithReason_data();
    void setNumbered_reserved_refusedWithReason();
    void call_arguments_savedAndGivenBack();
    void named_localPerCall_globalShared();
    void offsets_changedByTheProgram_refused();
    void input_afterM66_whatItWaitedFor();
    void returned_valueAndFlag();
};

namespace {
NgcParameters withOffsets()
{
    CoordinateSystems systems;
    systems[0] = {{QStringLiteral("X"), 10.0}, {QStringLiteral("Z"), -5.0}};
    systems[1] = {{QStringLiteral("Y"), 7.5}};
    return NgcParameters(systems, 1); // G55 active
}
} // namespace

void TestNgcParameters::numbered_unset_readsZero()
{
    NgcParameters p = withOffsets();
    QString why;
    QCOMPARE(p.numbered(1, &why), std::optional<double>(0.0));
    QCOMPARE(p.numbered(5000, &why), std::optional<double>(0.0));
    QVERIFY(p.setNumbered(31, 2.5).isEmpty());
    QCOMPARE(p.numbered(31, &why), std::optional<double>(2.5));
}

void TestNgcParameters::numbered_reserved_tiedOrRefused_data()
{
    QTest::addColumn<int>("number");
    QTest::addColumn<double>("value"); // NaN: refused
    QTest::addColumn<QString>("reason");
    const double refused = std::numeric_limits<double>::quiet_NaN();
    QTest::newRow("#5220 the active system (G55)") << 5220 << 2.0 << "";
    QTest::newRow("#5221 G54 X") << 5221 << 10.0 << "";
    QTest::newRow("#5223 G54 Z") << 5223 << -5.0 << "";
    QTest::newRow("#5222 G54 Y (none)") << 5222 << 0.0 << "";
    QTest::newRow("#5242 G55 Y") << 5242 << 7.5 << "";
    QTest::newRow("#5230 G54 R") << 5230 << 0.0 << "";
    QTest::newRow("#5211 G92 X at the start") << 5211 << 0.0 << "";
    QTest::newRow("#5321 G59 X") << 5321 << 0.0 << "";
    QTest::newRow("#5341 G59.1 X") << 5341 << refused << "G54..G59";
    QTest::newRow("#5399 before any M66") << 5399 << refused << "no M66 has run";
    QTest::newRow("#5400 tool") << 5400 << refused << "tool";
    QTest::newRow("#5421 position") << 5421 << refused << "position";
    QTest::newRow("#5061 probing") << 5061 << refused << "prob";
    QTest::newRow("#5161 G28 position") << 5161 << refused << "G28";
    QTest::newRow("#5500 none") << 5500 << refused << "not a parameter";
}

void TestNgcParameters::numbered_reserved_tiedOrRefused()
{
    QFETCH(int, number);
    QFETCH(double, value);
    QFETCH(QString, reason);
    const NgcParameters p = withOffsets();
    QString why;
    const std::optional<double> v = p.numbered(number, &why);
    if (std::isnan(value)) {
        QVERIFY(!v);
        QVERIFY2(why.contains(reason), qPrintable(why));
    } else {
        QCOMPARE(v, std::optional<double>(value));
    }
}

void TestNgcParameters::setNumbered_reserved_refusedWithReason_data()
{
    QTest::addColumn<int>("number");
    QTest::addColumn<QString>("reason");
    QTest::newRow("offset") << 5221 << "G10 L2";
    QTest::newRow("system") << 5220 << "read-only";
    QTest::newRow("M66") << 5399 << "read-only";
    QTest::newRow("position") << 5420 << "read-only";
    QTest::newRow("beyond") << 6000 << "not a parameter";
}

void TestNgcParameters::setNumbered_reserved_refusedWithReason()
{
    QFETCH(int, number);
    QFETCH(QString, reason);
    NgcParameters p = withOffsets();
    const QString why = p.setNumbered(number, 1.0);
    QVERIFY2(why.contains(reason), qPrintable(why));
}

void TestNgcParameters::call_arguments_savedAndGivenBack()
{
    NgcParameters p = withOffsets();
    QString why;
    p.setNumbered(1, 11);
    p.setNumbered(30, 30);
    p.setNumbered(31, 31);
    p.enterCall({1.5, 2.5});
    QCOMPARE(p.callLevel(), 1);
    QCOMPARE(p.numbered(1, &why), std::optional<double>(1.5));
    QCOMPARE(p.numbered(2, &why), std::optional<double>(2.5));
    QCOMPARE(p.numbered(30, &why), std::optional<double>(0.0));  // not passed: 0
    QCOMPARE(p.numbered(31, &why), std::optional<double>(31.0)); // global
    p.setNumbered(1, 99);
    p.setNumbered(31, 32);
    p.leaveCall();
    QCOMPARE(p.callLevel(), 0);
    QCOMPARE(p.numbered(1, &why), std::optional<double>(11.0));
    QCOMPARE(p.numbered(30, &why), std::optional<double>(30.0));
    QCOMPARE(p.numbered(31, &why), std::optional<double>(32.0));
}

void TestNgcParameters::named_localPerCall_globalShared()
{
    NgcParameters p = withOffsets();
    QString why;
    p.setNamed(QStringLiteral("depth"), 3);
    p.setNamed(QStringLiteral("_feed"), 300);
    p.enterCall({});
    QVERIFY(!p.named(QStringLiteral("depth"), &why));
    QVERIFY(why.contains(QStringLiteral("local")));
    QVERIFY(!p.exists(QStringLiteral("depth")));
    QCOMPARE(p.named(QStringLiteral("_feed"), &why), std::optional<double>(300.0));
    p.setNamed(QStringLiteral("depth"), 9);
    p.setNamed(QStringLiteral("_feed"), 400);
    QCOMPARE(p.named(QStringLiteral("_call_level"), &why), std::optional<double>(1.0));
    p.leaveCall();
    QCOMPARE(p.named(QStringLiteral("depth"), &why), std::optional<double>(3.0));
    QCOMPARE(p.named(QStringLiteral("_feed"), &why), std::optional<double>(400.0));
    QVERIFY(!p.named(QStringLiteral("_x"), &why));
    QVERIFY2(why.contains(QStringLiteral("run time")), qPrintable(why));
}

void TestNgcParameters::offsets_changedByTheProgram_refused()
{
    NgcParameters p = withOffsets();
    QString why;
    p.noteSystem(0);
    QCOMPARE(p.numbered(5220, &why), std::optional<double>(1.0));
    p.noteOffsetsChanged(12);
    QVERIFY(!p.numbered(5221, &why));
    QVERIFY2(why.contains(QStringLiteral("line 12")), qPrintable(why));
    p.noteAxisOffsetChanged(14);
    QVERIFY(!p.numbered(5211, &why));
    QVERIFY2(why.contains(QStringLiteral("line 14")), qPrintable(why));
}

void TestNgcParameters::input_afterM66_whatItWaitedFor()
{
    NgcParameters p = withOffsets();
    QString why;
    p.noteInput(1.0, 4);
    QCOMPARE(p.numbered(5399, &why), std::optional<double>(1.0));
    p.noteInput(0.0, 9);
    QCOMPARE(p.numbered(5399, &why), std::optional<double>(0.0));
    QVERIFY(!p.setNumbered(5399, 1.0).isEmpty());
}

void TestNgcParameters::returned_valueAndFlag()
{
    NgcParameters p = withOffsets();
    QString why;
    p.setReturned(4.5);
    QCOMPARE(p.named(QStringLiteral("_value"), &why), std::optional<double>(4.5));
    QCOMPARE(p.named(QStringLiteral("_value_returned"), &why), std::optional<double>(1.0));
    p.setReturned(std::nullopt);
    QCOMPARE(p.named(QStringLiteral("_value_returned"), &why), std::optional<double>(0.0));
}

STEPDECK_TEST_GUILESS_MAIN(TestNgcParameters)
#include "tst_ngcparameters.moc"
