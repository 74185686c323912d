// A controller's names for its axes (issue 32, step 3): valid names, default names kept for
// their own axes, and the ordered bus list of --axes and machine files ("feeder=5,gate=6").
#include "TestMain.h"
#include "model/AxisNames.h"
#include <QtTest>

using namespace stepdeck;

class TestAxisNames : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void isValidName_data();
    void isValidName();
    void setName_namesAndFinds();
    void setName_refusesWithReason_data();
    void setName_refusesWithReason();
    void assignBusAxes_defaultNamesKeepAxesOthersFillInOrder_data();
    void assignBusAxes_defaultNamesKeepAxesOthersFillInOrder();
    void assignBusAxes_refusesWithReason_data();
    void assignBusAxes_refusesWithReason();
    void assignBusAxes_fullBus_254Drives();
    void parseNamedAddresses_data();
    void parseNamedAddresses();
    void namedAddresses_roundTrip();
};

void TestAxisNames::isValidName_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("valid");
    QTest::newRow("word") << "feeder" << true;
    QTest::newRow("digits and _") << "gate_2" << true;
    QTest::newRow("letter X") << "X" << true;
    QTest::newRow("letter u") << "u" << true;
    QTest::newRow("letter A") << "A" << false; // the machine's axis A?
    QTest::newRow("letter Q") << "Q" << false;
    QTest::newRow("two letters") << "Qx" << true;
    QTest::newRow("empty") << "" << false;
    QTest::newRow("digit first") << "2gate" << false;
    QTest::newRow("underscore first") << "_gate" << false;
    QTest::newRow("space") << "feed er" << false;
    QTest::newRow("dash") << "feed-er" << false;
    QTest::newRow("umlaut") << QStringLiteral("f\u00fcller") << false;
    QTest::newRow("32 long") << QString(32, QLatin1Char('a')) << true;
    QTest::newRow("33 long") << QString(33, QLatin1Char('a')) << false;
}

void TestAxisNames::isValidName()
{
    QFETCH(QString, name);
    QFETCH(bool, valid);
    QCOMPARE(AxisNames::isValidName(name), valid);
}

void TestAxisNames::setName_namesAndFinds()
{
    AxisNames names;
    QString error;
    QVERIFY(names.setName(Axis::X, QStringLiteral("feeder"), &error));
    QCOMPARE(names.name(Axis::X), QStringLiteral("feeder"));
    QCOMPARE(names.name(Axis::Y), QStringLiteral("Y"));
    QCOMPARE(names.find(u"FEEDER"), Axis::X);
    QCOMPARE(names.find(u"X"), Axis::X); // a default name always means its axis
    QCOMPARE(names.find(u"Y"), Axis::Y);
    QCOMPARE(names.find(u"gate"), std::nullopt);
    // The default name of the axis itself takes its own name away.
    QVERIFY(names.setName(Axis::X, QStringLiteral("x"), &error));
    QVERIFY(names.isEmpty());
    QCOMPARE(names.name(Axis::X), QStringLiteral("X"));
}

void TestAxisNames::setName_refusesWithReason_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("reason");
    QTest::newRow("invalid") << "2gate"
                             << "is not an axis name";
    QTest::newRow("another's default") << "Y"
                                       << "Y is the name of another axis";
    QTest::newRow("another's fifth") << "AXIS5"
                                     << "axis5 is the name of another axis";
    QTest::newRow("taken") << "GATE"
                           << "GATE names two axes";
}

void TestAxisNames::setName_refusesWithReason()
{
    QFETCH(QString, name);
    QFETCH(QString, reason);
    AxisNames names;
    QString error;
    QVERIFY(names.setName(Axis::Z, QStringLiteral("gate"), &error));
    const AxisNames before = names;
    QVERIFY(!names.setName(Axis::X, name, &error));
    QVERIFY2(error.contains(reason), qPrintable(error));
    QCOMPARE(names, before);
}

void TestAxisNames::assignBusAxes_defaultNamesKeepAxesOthersFillInOrder_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected"); // in axis order: index:name=address
    QTest::newRow("letters") << "X=1,Y=2,Z=3"
                             << "0:X=1 1:Y=2 2:Z=3";
    QTest::newRow("letters reordered") << "Z=3,X=1"
                                       << "0:X=1 2:Z=3";
    QTest::newRow("Y alone stays Y") << "Y=2"
                                     << "1:Y=2";
    QTest::newRow("names in order") << "feeder=5,gate=6,press=7"
                                    << "0:feeder=5 1:gate=6 2:press=7";
    QTest::newRow("names around a letter") << "feeder=5,X=1,gate=6"
                                           << "0:X=1 1:feeder=5 2:gate=6";
    QTest::newRow("fifth by default name") << "axis5=9,feeder=1"
                                           << "0:feeder=1 4:axis5=9";
}

void TestAxisNames::assignBusAxes_defaultNamesKeepAxesOthersFillInOrder()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    QList<NamedAddress> list;
    QString error;
    QVERIFY2(stepdeck::parseNamedAddresses(text, &list, &error), qPrintable(error));
    QMap<Axis, int> addresses;
    AxisNames names;
    QVERIFY2(assignBusAxes(list, &addresses, &names, &error), qPrintable(error));
    QStringList got;
    for (auto it = addresses.cbegin(); it != addresses.cend(); ++it)
        got << QStringLiteral("%1:%2=%3")
                   .arg(it.key().index())
                   .arg(names.name(it.key()))
                   .arg(it.value());
    QCOMPARE(got.join(QLatin1Char(' ')), expected);
}

void TestAxisNames::assignBusAxes_refusesWithReason_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("name twice") << "feeder=5,FEEDER=6"
                                << "FEEDER is given twice";
    QTest::newRow("letter twice") << "X=1,x=2"
                                  << "x is given twice";
}

void TestAxisNames::assignBusAxes_refusesWithReason()
{
    QFETCH(QString, text);
    QFETCH(QString, reason);
    QList<NamedAddress> list;
    QString error;
    QVERIFY(stepdeck::parseNamedAddresses(text, &list, &error));
    QMap<Axis, int> addresses{{Axis::U, 9}};
    AxisNames names;
    QVERIFY(!assignBusAxes(list, &addresses, &names, &error));
    QVERIFY2(error.contains(reason), qPrintable(error));
    QCOMPARE(addresses, (QMap<Axis, int>{{Axis::U, 9}})); // untouched on failure
}

void TestAxisNames::assignBusAxes_fullBus_254Drives()
{
    QList<NamedAddress> list;
    for (int address = 1; address <= 254; ++address)
        list << NamedAddress{QStringLiteral("drive%1").arg(address), address};
    QMap<Axis, int> addresses;
    AxisNames names;
    QString error;
    QVERIFY2(assignBusAxes(list, &addresses, &names, &error), qPrintable(error));
    QCOMPARE(addresses.size(), 254);
    QCOMPARE(addresses.value(Axis::at(253)), 254);
    QCOMPARE(names.name(Axis::at(253)), QStringLiteral("drive254"));
    list << NamedAddress{QStringLiteral("oneMore"), 255};
    QVERIFY(!assignBusAxes(list, &addresses, &names, &error));
    QVERIFY2(error.contains(QStringLiteral("more than 254 axes")), qPrintable(error));
}

void TestAxisNames::parseNamedAddresses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error"); // empty: parses
    QTest::newRow("two") << "feeder=5, gate=6"
                         << "";
    QTest::newRow("no address") << "feeder"
                                << "expected NAME=ADDRESS";
    QTest::newRow("bad name") << "2x=5"
                              << "'2x' is not an axis name";
    QTest::newRow("one other letter") << "A=5"
                                      << "'A' is not an axis name";
    QTest::newRow("not a number") << "feeder=five"
                                  << "is not a whole bus address";
    QTest::newRow("fraction") << "feeder=1.5"
                              << "is not a whole bus address";
    QTest::newRow("negative") << "feeder=-1"
                              << "is not a whole bus address";
    QTest::newRow("nothing") << " , "
                             << "no axis given";
}

void TestAxisNames::parseNamedAddresses()
{
    QFETCH(QString, text);
    QFETCH(QString, error);
    QList<NamedAddress> list;
    QString why;
    QCOMPARE(stepdeck::parseNamedAddresses(text, &list, &why), error.isEmpty());
    if (error.isEmpty()) {
        QCOMPARE(list.size(), 2);
        QCOMPARE(list.at(1).name, QStringLiteral("gate"));
        QCOMPARE(list.at(1).address, 6);
    } else {
        QVERIFY2(why.contains(error), qPrintable(why));
    }
}

void TestAxisNames::namedAddresses_roundTrip()
{
    QList<NamedAddress> list;
    QString error;
    QVERIFY(stepdeck::parseNamedAddresses(QStringLiteral("feeder=5,Z=3,gate=6"), &list, &error));
    QMap<Axis, int> addresses;
    AxisNames names;
    QVERIFY(assignBusAxes(list, &addresses, &names, &error));
    const QList<NamedAddress> back = namedAddresses(addresses, names);
    QStringList text;
    for (const NamedAddress& e : back)
        text << QStringLiteral("%1=%2").arg(e.name).arg(e.address);
    QCOMPARE(text.join(QLatin1Char(',')), QStringLiteral("feeder=5,gate=6,Z=3"));
    QMap<Axis, int> again;
    AxisNames againNames;
    QVERIFY(assignBusAxes(back, &again, &againNames, &error));
    QCOMPARE(again, addresses);
    QCOMPARE(againNames, names);
}

STEPDECK_TEST_GUILESS_MAIN(TestAxisNames)
#include "tst_axisnames.moc"
