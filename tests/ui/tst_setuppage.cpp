// Setup pages generated from the schema: a form write produces the exact E-LAB bytes, an
// out-of-range entry cannot be written and says why, files round-trip in the CLI's JSON
// format, and a loaded file is compared with the form before anything is written.
#include "UiTestSupport.h"
#include "setup/DiffDialog.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include "setup/WriteWarnings.h"
#include <QJsonDocument>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
void type(ui::ParameterField* field, const QString& text)
{
    QLineEdit* edit = field->lineEdit();
    edit->selectAll();
    QTest::keyClicks(edit, text);
}
} // namespace

class TestSetupPage : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void form_generatedFromSchema_groupsAndAxisColumns();
    void write_firstTime_sendsEveryParameterWithExactBytes_data();
    void write_firstTime_sendsEveryParameterWithExactBytes();
    void write_changedField_sendsOnlyItsCommand();
    void outOfRange_cannotBeWrittenAndSaysWhy_data();
    void outOfRange_cannotBeWrittenAndSaysWhy();
    void file_saveAndRead_roundTripsInCliFormat();
    void file_broken_rejectedWithReason();
    void diff_loadedFile_listsChangedValues();
    void warnings_collectedForParametersThatCarryThem();

private:
    ui::SetupPage* page() const { return m_f->window->setupPage(); }
    bool writeAndWait(bool verify);
    std::unique_ptr<UiFixture> m_f;
};

void TestSetupPage::init()
{
    QSettings().clear();
    m_f = std::make_unique<UiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectSim());
}

bool TestSetupPage::writeAndWait(bool verify)
{
    if (!page()->write(verify))
        return false;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 5000) {
        const QString text = page()->messageText();
        if (text.startsWith(QStringLiteral("Written")))
            return true;
        if (text.contains(QStringLiteral("failed")))
            return false;
        QTest::qWait(10);
    }
    return false;
}

void TestSetupPage::form_generatedFromSchema_groupsAndAxisColumns()
{
    const ParameterSchema schema = m_f->window->context()->schema();
    for (const ParameterSpec& spec : schema.specs()) {
        if (spec.perAxis) {
            for (Axis a : {Axis::X, Axis::Y, Axis::Z})
                QVERIFY2(page()->field(spec.name, a), qPrintable(spec.name));
            QVERIFY(!page()->field(spec.name, Axis::U));
        } else {
            QVERIFY2(page()->field(spec.name), qPrintable(spec.name));
        }
    }
    // E-LAB cannot read parameters back: no Read button.
    QVERIFY(!page()->readButton()->isVisible());
}

void TestSetupPage::write_firstTime_sendsEveryParameterWithExactBytes_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("values"); // X,Y,Z or one global value
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("start speed") << QStringLiteral("start-speed")
                                 << QStringList{"100", "100", "100"}
                                 << QByteArray("\x1bS0064,0064;0064.");
    QTest::newRow("max speed") << QStringLiteral("max-speed") << QStringList{"1000", "2000", "3000"}
                               << QByteArray("\x1bM03E8,07D0;0BB8.");
    QTest::newRow("acceleration") << QStringLiteral("acceleration")
                                  << QStringList{"500", "1000", "2000"}
                                  << QByteArray("\x1b"
                                                "A01F4,03E8;07D0.");
    QTest::newRow("feed speed") << QStringLiteral("feed-speed") << QStringList{"10", "20", "30"}
                                << QByteArray("\x1c"
                                              "000A,0014;001E.");
    QTest::newRow("drive power") << QStringLiteral("drive-power") << QStringList{"50"}
                                 << QByteArray("\x02"
                                               "32");
}

void TestSetupPage::write_firstTime_sendsEveryParameterWithExactBytes()
{
    QFETCH(QString, name);
    QFETCH(QStringList, values);
    QFETCH(QByteArray, expected);
    if (values.size() == 1) {
        type(page()->field(name), values.first());
    } else {
        const QList<Axis> axes{Axis::X, Axis::Y, Axis::Z};
        for (int i = 0; i < 3; ++i)
            type(page()->field(name, axes[i]), values[i]);
    }
    const qsizetype start = m_f->records.size();
    QVERIFY(page()->writeButton()->isEnabled());
    QVERIFY(writeAndWait(false));
    QVERIFY2(m_f->sent(start).contains(expected), qPrintable(elab::toMnemonics(m_f->sent(start))));
}

void TestSetupPage::write_changedField_sendsOnlyItsCommand()
{
    QVERIFY(writeAndWait(false)); // everything once: the device values are known now
    ui::ParameterField* field = page()->field(QStringLiteral("start-speed"), Axis::Y);
    QVERIFY(!field->isChanged());
    type(field, QStringLiteral("200"));
    QVERIFY(field->isChanged());
    QCOMPARE(field->lineEdit()->property("fieldState").toString(), QStringLiteral("changed"));
    const qsizetype start = m_f->records.size();
    QVERIFY(writeAndWait(false));
    // The standstill read (<HT><ENQ>) precedes every setup write.
    QCOMPARE(elab::toMnemonics(m_f->sent(start)), QStringLiteral("<HT><ENQ><ESC>S0064,00C8;0064."));
    QVERIFY(!field->isChanged());
    QVERIFY(!writeAndWait(false)); // nothing left to write
}

void TestSetupPage::outOfRange_cannotBeWrittenAndSaysWhy_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("text");
    QTest::newRow("speed above 16 bits")
        << QStringLiteral("start-speed") << QStringLiteral("70000");
    QTest::newRow("negative speed") << QStringLiteral("max-speed") << QStringLiteral("-5");
    QTest::newRow("not a number") << QStringLiteral("acceleration") << QStringLiteral("fast");
    QTest::newRow("power above 100") << QStringLiteral("drive-power") << QStringLiteral("101");
    QTest::newRow("empty") << QStringLiteral("feed-speed") << QString();
}

void TestSetupPage::outOfRange_cannotBeWrittenAndSaysWhy()
{
    QFETCH(QString, name);
    QFETCH(QString, text);
    const ParameterSchema schema = m_f->window->context()->schema();
    const ParameterSpec* spec = schema.find(name);
    ui::ParameterField* field =
        page()->field(name, spec->perAxis ? std::optional<Axis>(Axis::X) : std::nullopt);
    type(field, text);
    if (text.isEmpty())
        field->lineEdit()->clear();
    QVERIFY(!field->isValid());
    QCOMPARE(field->lineEdit()->property("fieldState").toString(), QStringLiteral("invalid"));
    QVERIFY(!page()->writeButton()->isEnabled());
    QVERIFY(!page()->writeVerifyButton()->isEnabled());
    QVERIFY2(page()->writeButton()->toolTip().contains(name),
             qPrintable(page()->writeButton()->toolTip()));
    const qsizetype start = m_f->records.size();
    QVERIFY(!page()->write(false)); // even when called directly
    QVERIFY(page()->messageText().contains(QStringLiteral("cannot be written")));
    QVERIFY(page()->messageText().contains(name));
    QVERIFY(m_f->sent(start).isEmpty());
}

void TestSetupPage::file_saveAndRead_roundTripsInCliFormat()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    type(page()->field(QStringLiteral("max-speed"), Axis::Z), QStringLiteral("4321"));
    QString error;
    QVERIFY2(page()->saveToFile(path, &error), qPrintable(error));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(json.value(QStringLiteral("format")).toString(),
             QStringLiteral("stepdeck-parameters"));
    QCOMPARE(json.value(QStringLiteral("model")).toString(), QStringLiteral("elab"));
    QCOMPARE(json.value(QStringLiteral("parameters"))
                 .toObject()
                 .value(QStringLiteral("max-speed"))
                 .toObject()
                 .value(QStringLiteral("Z"))
                 .toInt(),
             4321);

    page()->resetToDefaults();
    ParameterSet loaded;
    QVERIFY2(page()->readFile(path, &loaded, &error), qPrintable(error));
    page()->applyToForm(loaded);
    QCOMPARE(page()->field(QStringLiteral("max-speed"), Axis::Z)->value().toLongLong(), 4321);
}

void TestSetupPage::file_broken_rejectedWithReason()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format":"stepdeck-parameters","version":1,"model":"elab",
                  "parameters":{"drive-power":250}})");
    file.close();
    ParameterSet loaded;
    QString error;
    QVERIFY(!page()->readFile(path, &loaded, &error));
    QVERIFY2(error.contains(QStringLiteral("drive-power")), qPrintable(error));
}

void TestSetupPage::diff_loadedFile_listsChangedValues()
{
    ParameterSet current;
    QVERIFY(page()->formValues(&current, nullptr));
    ParameterSet loaded = current;
    loaded[QStringLiteral("max-speed")].perAxis[Axis::Y] = qint64(1234);
    const QList<ui::DiffDialog::Row> rows =
        ui::DiffDialog::compare(m_f->window->context()->schema(), current, loaded);
    int changed = 0;
    for (const ui::DiffDialog::Row& r : rows) {
        if (r.differs) {
            ++changed;
            QCOMPARE(r.axis, QStringLiteral("Y"));
            QCOMPARE(r.loaded, QStringLiteral("1234"));
        }
    }
    QCOMPARE(changed, 1);
}

void TestSetupPage::warnings_collectedForParametersThatCarryThem()
{
    ParameterSpec address;
    address.name = QStringLiteral("motor-address");
    address.label = QStringLiteral("Motor address");
    address.warning = QStringLiteral("communication continues at the new address");
    ParameterSpec plain;
    plain.name = QStringLiteral("backlash");
    const ParameterSchema schema({address, plain});
    ParameterSet set;
    set[QStringLiteral("backlash")].global = qint64(3);
    QVERIFY(ui::WriteWarnings::collect(schema, set).isEmpty());
    set[QStringLiteral("motor-address")].global = qint64(4);
    const QStringList warnings = ui::WriteWarnings::collect(schema, set);
    QCOMPARE(warnings.size(), 1);
    QVERIFY(warnings.first().contains(QStringLiteral("new address")));
}

QTEST_MAIN(TestSetupPage)
#include "tst_setuppage.moc"
