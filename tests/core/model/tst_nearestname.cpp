// "Did you mean ...?" (issue 16): the nearest known name within a small edit distance or the
// only name the typed text begins, nothing when no name is close or the choice is a guess.
#include "TestMain.h"
#include "model/NearestName.h"
#include <QtTest>

using namespace stepdeck;

class TestNearestName : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void editDistance_countsEditsAndSwaps_data();
    void editDistance_countsEditsAndSwaps();
    void nearest_commands_data();
    void nearest_commands();
};

void TestNearestName::editDistance_countsEditsAndSwaps_data()
{
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<int>("distance");
    QTest::newRow("equal") << "status"
                           << "status" << 0;
    QTest::newRow("case only") << "STATUS"
                               << "status" << 0;
    QTest::newRow("swap") << "stauts"
                          << "status" << 1;
    QTest::newRow("missing letter") << "mve"
                                    << "move" << 1;
    QTest::newRow("extra letter") << "homme"
                                  << "home" << 1;
    QTest::newRow("two substitutions") << "max-sped"
                                       << "max-speed" << 1;
    QTest::newRow("empty") << ""
                           << "jog" << 3;
    QTest::newRow("unrelated") << "frobnicate"
                               << "feed" << 9;
}

void TestNearestName::editDistance_countsEditsAndSwaps()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    QTEST(names::editDistance(a, b), "distance");
    QTEST(names::editDistance(b, a), "distance");
}

void TestNearestName::nearest_commands_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("expected");
    QTest::newRow("swapped letters") << "stauts"
                                     << "status";
    QTest::newRow("one letter missing") << "mve"
                                        << "move";
    QTest::newRow("two edits") << "exprt"
                               << "export";
    QTest::newRow("upper case") << "STATSU"
                                << "status";
    QTest::newRow("only prefix") << "laser"
                                 << "laser-bridge";
    QTest::newRow("ambiguous prefix") << "sto"
                                      << "stop"; // one edit from stop, two from store
    QTest::newRow("too short to guess") << "st"
                                        << "";
    QTest::newRow("nothing close") << "frobnicate"
                                   << "";
    QTest::newRow("exact name") << "status"
                                << "";
    QTest::newRow("three letters, two edits") << "xyz"
                                              << "";
}

void TestNearestName::nearest_commands()
{
    QFETCH(QString, typed);
    const QStringList commands{"ports",  "models", "params", "status",      "set",  "get",
                               "export", "import", "move",   "jog",         "home", "stop",
                               "store",  "panic",  "reset",  "laser-bridge"};
    QTEST(names::nearest(typed, commands), "expected");
}

STEPDECK_TEST_GUILESS_MAIN(TestNearestName)
#include "tst_nearestname.moc"
