// WordMap: QMap's interface and order for a line's few words, kept in place (issue 29). Each
// sequence of operations is run on a WordMap and on a QMap; both must agree at every step.
#include "TestMain.h"
#include "program/WordMap.h"
#include <QMap>
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck::program;

class TestWordMap : public QObject
{
    Q_OBJECT
private slots:
    void operations_anySequence_agreeWithQMap_data();
    void operations_anySequence_agreeWithQMap();
    void insert_existingKey_replacesInPlace();
    void remove_missingKey_changesNothing();
    void storage_pastPrealloc_keepsEveryEntry();
    void equality_sameEntries_equalWhateverTheOrderOfInsertion();
    void iterators_rangeForAndKeys_giveValuesInKeyOrder();
};

namespace {

// Compares every observable of the two maps; an empty string when they agree.
QString differences(const WordMap<QString, double, 4>& flat, const QMap<QString, double>& map)
{
    if (flat.size() != map.size())
        return QStringLiteral("size %1, QMap %2").arg(flat.size()).arg(map.size());
    if (flat.keys() != map.keys())
        return QStringLiteral("keys %1, QMap %2")
            .arg(flat.keys().join(QLatin1Char(',')), map.keys().join(QLatin1Char(',')));
    if (flat.values() != map.values())
        return QStringLiteral("values differ");
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        if (!flat.contains(it.key()) || flat.value(it.key()) != it.value())
            return QStringLiteral("value of %1").arg(it.key());
    if (!map.isEmpty() && (flat.firstKey() != map.firstKey() || flat.lastKey() != map.lastKey() ||
                           flat.first() != map.first() || flat.last() != map.last()))
        return QStringLiteral("first or last differs");
    return {};
}

} // namespace

void TestWordMap::operations_anySequence_agreeWithQMap_data()
{
    QTest::addColumn<quint32>("seed");
    for (quint32 seed : {1u, 7u, 42u, 1234u, 99991u})
        QTest::addRow("seed %u", seed) << seed;
}

void TestWordMap::operations_anySequence_agreeWithQMap()
{
    QFETCH(quint32, seed);
    QRandomGenerator random(seed);
    const QStringList keys{"X", "Y", "Z", "A", "B", "C", "U", "V", "W", "F", "XX"};
    WordMap<QString, double, 4> flat; // a small prealloc: the heap path runs too
    QMap<QString, double> map;
    for (int step = 0; step < 2000; ++step) {
        const QString key = keys.at(random.bounded(int(keys.size())));
        const double value = random.bounded(1000);
        switch (random.bounded(5)) {
        case 0:
        case 1:
            flat.insert(key, value);
            map.insert(key, value);
            break;
        case 2:
            QCOMPARE(flat.remove(key), map.remove(key));
            break;
        case 3:
            flat[key] += value;
            map[key] += value;
            break;
        default:
            QCOMPARE(flat.take(key), map.take(key));
            break;
        }
        const QString why = differences(flat, map);
        QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("step %1: %2").arg(step).arg(why)));
    }
}

void TestWordMap::insert_existingKey_replacesInPlace()
{
    WordMap<QString, int> m;
    m.insert(QStringLiteral("Y"), 1);
    m.insert(QStringLiteral("X"), 2);
    const auto it = m.insert(QStringLiteral("Y"), 3);
    QCOMPARE(it.key(), QStringLiteral("Y"));
    QCOMPARE(m.size(), 2);
    QCOMPARE(m.value(QStringLiteral("Y")), 3);
    QCOMPARE(m.keys(), (QStringList{"X", "Y"}));
}

void TestWordMap::remove_missingKey_changesNothing()
{
    WordMap<QChar, int> m{{QLatin1Char('F'), 15}, {QLatin1Char('I'), 3}};
    QCOMPARE(m.remove(QLatin1Char('J')), 0);
    QCOMPARE(m.size(), 2);
    QCOMPARE(m.value(QLatin1Char('J'), -1), -1);
    QVERIFY(m.constFind(QLatin1Char('J')) == m.cend());
    QCOMPARE(m.constFind(QLatin1Char('I')).value(), 3);
}

void TestWordMap::storage_pastPrealloc_keepsEveryEntry()
{
    WordMap<int, int, 2> m;
    for (int i = 20; i > 0; --i)
        m.insert(i, i * i);
    QCOMPARE(m.size(), 20);
    int expected = 1;
    for (auto it = m.cbegin(); it != m.cend(); ++it, ++expected) {
        QCOMPARE(it.key(), expected);
        QCOMPARE(it.value(), expected * expected);
    }
    const WordMap<int, int, 2> copy = m;
    QCOMPARE(copy.size(), 20);
    QVERIFY(copy == m);
}

void TestWordMap::equality_sameEntries_equalWhateverTheOrderOfInsertion()
{
    const WordMap<QString, double> a{{"X", 1}, {"Z", 2}};
    WordMap<QString, double> b;
    b.insert(QStringLiteral("Z"), 2);
    b.insert(QStringLiteral("X"), 1);
    QVERIFY(a == b);
    b.insert(QStringLiteral("X"), 1.5);
    QVERIFY(a != b);
}

void TestWordMap::iterators_rangeForAndKeys_giveValuesInKeyOrder()
{
    WordMap<QString, double> m{{"Z", 3}, {"X", 1}, {"Y", 2}};
    QList<double> values;
    for (double v : m)
        values << v;
    QCOMPARE(values, (QList<double>{1, 2, 3}));
    for (auto it = m.begin(); it != m.end(); ++it)
        it.value() *= 10;
    QCOMPARE(m.values(), (QList<double>{10, 20, 30}));
    m.erase(m.constFind(QStringLiteral("Y")));
    QCOMPARE(m.keys(), (QStringList{"X", "Z"}));
}

STEPDECK_TEST_GUILESS_MAIN(TestWordMap)
#include "tst_wordmap.moc"
