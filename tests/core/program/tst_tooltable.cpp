// A machine's tool table in LinuxCNC's tool.tbl format (ToolTable, issue 29): the columns
// StepDeck uses, the ones it reads past, comments, CRLF, every error at its line and column,
// and the text it writes reads back to the same table.
#include "TestMain.h"
#include "program/ToolTable.h"
#include <QtTest>

using namespace stepdeck::program;

namespace {
QString describeTools(const ToolTable& table)
{
    QStringList out;
    for (const Tool& t : table.tools())
        out << QStringLiteral("T%1 L%2 D%3 \"%4\"")
                   .arg(t.number)
                   .arg(t.length)
                   .arg(t.diameter)
                   .arg(t.text);
    return out.join(QLatin1String(" | "));
}
} // namespace

class TestToolTable : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_tables_golden_data();
    void parse_tables_golden();
    void parse_invalid_lineColumnAndMessage_data();
    void parse_invalid_lineColumnAndMessage();
    void text_writtenTable_readsBackTheSame();
};

void TestToolTable::parse_tables_golden_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("tools");
    QTest::newRow("empty") << QByteArray() << QString();
    QTest::newRow("LinuxCNC's columns")
        << QByteArray("T1 P1 Z12.5 D6 ;6 mm end mill\nT2 P2 X0 Y0 Z+30.25 D3.175 ;1/8\" drill\n")
        << "T1 L12.5 D6 \"6 mm end mill\" | T2 L30.25 D3.175 \"1/8\" drill\"";
    QTest::newRow("comments, blank lines, CRLF, lower case")
        << QByteArray("; my mill\r\n\r\nt5 z-1.5\r\n") << "T5 L-1.5 D0 \"\"";
    QTest::newRow("in any order") << QByteArray("D2 Z4 T7 P3") << "T7 L4 D2 \"\"";
}

void TestToolTable::parse_tables_golden()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, tools);
    QList<ProgramError> errors;
    const std::optional<ToolTable> table = ToolTable::parse(text, &errors);
    QVERIFY2(table, qPrintable(errors.isEmpty() ? QString() : errors.first().text()));
    QCOMPARE(describeTools(*table), tools);
    QVERIFY(errors.isEmpty());
}

void TestToolTable::parse_invalid_lineColumnAndMessage_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("error");
    QTest::newRow("unknown column") << QByteArray("T1 Z1\nT2 K5") << "2:4: K5 is not a column";
    QTest::newRow("not a number") << QByteArray("T1 Zabc") << "1:4: Zabc is not a column";
    QTest::newRow("no tool number") << QByteArray("Z5 D2 ;x") << "1:1: the line names no tool (T)";
    QTest::newRow("fraction") << QByteArray("T1.5 Z1") << "1:1: T1.5: T takes a tool number";
    QTest::newRow("negative diameter")
        << QByteArray("T1 D-2") << "1:4: D-2: a diameter is not below 0";
    QTest::newRow("twice") << QByteArray("T3 Z1\n\nT3 Z2") << "3:1: tool 3 is in the table twice";
}

void TestToolTable::parse_invalid_lineColumnAndMessage()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, error);
    QList<ProgramError> errors;
    QVERIFY(!ToolTable::parse(text, &errors));
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().text().startsWith(error), qPrintable(errors.first().text()));
}

void TestToolTable::text_writtenTable_readsBackTheSame()
{
    ToolTable table;
    table.insert(Tool{4, 41.125, 8, QStringLiteral("Fräser 8 mm")});
    table.insert(Tool{1, -0.5, 0, QString()});
    const std::optional<ToolTable> back = ToolTable::parse(table.text(), nullptr);
    QVERIFY(back);
    QCOMPARE(*back, table);
    QVERIFY(table.text().startsWith("T1 P1 Z-0.5 D0\n"));
}

STEPDECK_TEST_APPLESS_MAIN(TestToolTable)
#include "tst_tooltable.moc"
