// Setup pages generated from the schema: a form write produces the exact E-LAB bytes, an
// out-of-range entry cannot be written and says why (in the UI's words), files round-trip
// in the CLI's JSON format, and a loaded file is compared with the form before anything is
// written. E-LAB is write-only: after a reconnect or power cycle nothing counts as written,
// Write all always exists, and load-and-write writes the whole file.
#include "TestMain.h"
#include "UiTestSupport.h"
#include "setup/DiffDialog.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include "setup/WriteWarnings.h"
#include <QJsonDocument>
#include <QLabel>
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
    void acceleration_unitColumn_saysNoUnitWithManualTooltip();
    void write_firstTime_sendsEveryParameterWithExactBytes_data();
    void write_firstTime_sendsEveryParameterWithExactBytes();
    void write_changedField_sendsOnlyItsCommand();
    void outOfRange_cannotBeWrittenAndSaysWhy_data();
    void outOfRange_cannotBeWrittenAndSaysWhy();
    void file_saveAndRead_roundTripsInCliFormat();
    void file_broken_rejectedWithReason();
    void file_brokenJson_namesLineAndColumn();
    void diff_loadedFile_listsChangedValues();
    void warnings_collectedForParametersThatCarryThem();
    void write_afterReconnect_sendsEveryParameterAgain();
    void write_afterPowerCycle_sendsEveryParameterAgain();
    void writeAll_afterFullWrite_sendsEveryParameterAgain();
    void loadAndWrite_writesTheWholeFile();
    void nothingToWrite_saysWhy();
    void writeAndVerify_writeOnly_saysNothingVerified();
    void invalid_formAndFileSayTheSame();
    void invalid_everyReasonListed_messageStaysOneLine();

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

// Issue 31: "The Acceleration row has no unit". The manual gives none, so the row says so
// (the schema's unit note) and its tooltip quotes what the manual says about the scale.
void TestSetupPage::acceleration_unitColumn_saysNoUnitWithManualTooltip()
{
    auto* unit = page()->findChild<QLabel*>(QStringLiteral("unit-acceleration"));
    QVERIFY(unit);
    QCOMPARE(unit->text(), QStringLiteral("(no unit)"));
    QVERIFY2(unit->toolTip().contains(QStringLiteral("the steeper the ramp")),
             qPrintable(unit->toolTip()));
    auto* speed = page()->findChild<QLabel*>(QStringLiteral("unit-start-speed"));
    QVERIFY(speed);
    QCOMPARE(speed->text(), QStringLiteral("steps/s"));
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
    // Issue 12: a leading zero made the value octal ("0100" wrote 64 %). Decimal, always.
    QTest::newRow("leading zeros are decimal")
        << QStringLiteral("drive-power") << QStringList{"0100"}
        << QByteArray("\x02"
                      "64");
    QTest::newRow("per-axis leading zeros")
        << QStringLiteral("start-speed") << QStringList{"0100", "00100", "+100"}
        << QByteArray("\x1bS0064,0064;0064.");
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
    QTest::newRow("hex") << QStringLiteral("drive-power") << QStringLiteral("0x40");
    QTest::newRow("exponent") << QStringLiteral("max-speed") << QStringLiteral("1e3");
    QTest::newRow("nan") << QStringLiteral("acceleration") << QStringLiteral("nan");
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
    // Named as the form names it (translated label and axis), not by the file's key.
    const QString label = field->displayName();
    QVERIFY(label != name);
    QVERIFY2(page()->writeButton()->toolTip().contains(label),
             qPrintable(page()->writeButton()->toolTip()));
    const qsizetype start = m_f->records.size();
    QVERIFY(!page()->write(false)); // even when called directly
    QVERIFY(page()->messageText().contains(QStringLiteral("cannot be written")));
    QVERIFY2(page()->messageText().contains(label), qPrintable(page()->messageText()));
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

void TestSetupPage::file_brokenJson_namesLineAndColumn()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("typo.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    // A missing comma at the end of line 3: the parser stops at the next key, on line 4
    // (Qt's offset points just inside its opening quote: column 4).
    file.write("{\n  \"format\": \"stepdeck-parameters\",\n  \"version\": 1\n  \"model\": "
               "\"elab\"\n}\n");
    file.close();
    ParameterSet loaded;
    QString error;
    QVERIFY(!page()->readFile(path, &loaded, &error));
    QVERIFY2(error.contains(QStringLiteral("line 4, column 4")), qPrintable(error));
    QVERIFY(error.contains(QStringLiteral("typo.json")));
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

namespace {
// The setup commands of one full E-LAB write, in the order the page sends them.
QStringList setupCommands(const QString& mnemonics)
{
    QStringList out;
    for (const char* c : {"<ESC>S", "<ESC>M", "<ESC>A", "<FS>", "<STX>"}) {
        if (mnemonics.contains(QString::fromLatin1(c)))
            out << QString::fromLatin1(c);
    }
    return out;
}
const QStringList kEverySetupCommand{QStringLiteral("<ESC>S"), QStringLiteral("<ESC>M"),
                                     QStringLiteral("<ESC>A"), QStringLiteral("<FS>"),
                                     QStringLiteral("<STX>")};
} // namespace

void TestSetupPage::write_afterReconnect_sendsEveryParameterAgain()
{
    QVERIFY(writeAndWait(false));
    QVERIFY(!page()->write(false)); // all written in this session, nothing changed
    m_f->window->context()->disconnectFromController();
    QTRY_VERIFY(!m_f->window->context()->isConnected());
    QVERIFY(m_f->connectSim());
    // The board may have been reset or replaced meanwhile: nothing counts as written.
    QVERIFY(page()->field(QStringLiteral("max-speed"), Axis::X)->isChanged());
    const qsizetype start = m_f->deviceMark();
    QVERIFY(writeAndWait(false));
    QCOMPARE(setupCommands(elab::toMnemonics(m_f->deviceBytes().mid(start))), kEverySetupCommand);
}

void TestSetupPage::write_afterPowerCycle_sendsEveryParameterAgain()
{
    QVERIFY(writeAndWait(false));
    QTRY_VERIFY(!m_f->window->context()->status().setupIncomplete);
    QVERIFY(!page()->write(false));
    // The board loses power and comes back: it reports its setup incomplete again.
    QVERIFY(m_f->withSim([](elab::ElabSimulator* sim) { sim->powerOnReset(); }));
    QTRY_VERIFY(m_f->window->context()->status().setupIncomplete);
    QVERIFY(m_f->window->context()->knownParameters().isEmpty());
    const qsizetype start = m_f->deviceMark();
    QVERIFY(writeAndWait(false));
    QCOMPARE(setupCommands(elab::toMnemonics(m_f->deviceBytes().mid(start))), kEverySetupCommand);
    QTRY_VERIFY(!m_f->window->context()->status().setupIncomplete);
}

void TestSetupPage::writeAll_afterFullWrite_sendsEveryParameterAgain()
{
    QVERIFY(writeAndWait(false));
    QVERIFY(page()->writeAllButton()->isVisible());
    QVERIFY(page()->writeAllButton()->isEnabled());
    const qsizetype start = m_f->deviceMark();
    QVERIFY(page()->writeAll(false));
    QTRY_VERIFY(page()->messageText().startsWith(QStringLiteral("Written")));
    QTRY_COMPARE(setupCommands(elab::toMnemonics(m_f->deviceBytes().mid(start))),
                 kEverySetupCommand);
}

void TestSetupPage::loadAndWrite_writesTheWholeFile()
{
    QVERIFY(writeAndWait(false));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("same.json"));
    QString error;
    QVERIFY2(page()->saveToFile(path, &error), qPrintable(error));
    // The file holds what the board already has: "Load and write" still writes all of it.
    ui::DiffDialog* diff = page()->loadFile(path);
    QVERIFY(diff);
    QCOMPARE(diff->changedCount(), 0);
    QVERIFY(!diff->isModal());
    const qsizetype start = m_f->deviceMark();
    diff->done(ui::DiffDialog::LoadAndWrite);
    QTRY_VERIFY(page()->messageText().startsWith(QStringLiteral("Written")));
    QTRY_COMPARE(setupCommands(elab::toMnemonics(m_f->deviceBytes().mid(start))),
                 kEverySetupCommand);
}

void TestSetupPage::nothingToWrite_saysWhy()
{
    QVERIFY(writeAndWait(false));
    QVERIFY(!page()->write(false));
    QVERIFY2(page()->messageText().contains(QStringLiteral("written or read in this session")),
             qPrintable(page()->messageText()));
}

void TestSetupPage::writeAndVerify_writeOnly_saysNothingVerified()
{
    // Issue 16: E-LAB cannot read back; "Write & verify" must not read like a verified write.
    type(page()->field(QStringLiteral("drive-power")), QStringLiteral("40"));
    const qsizetype start = m_f->deviceMark();
    QVERIFY(writeAndWait(true));
    QVERIFY2(page()->messageText().startsWith(QStringLiteral("Written: ")),
             qPrintable(page()->messageText()));
    QVERIFY2(page()->messageText().contains(QStringLiteral("Nothing could be verified")),
             qPrintable(page()->messageText()));
    QVERIFY(!page()->messageText().contains(QStringLiteral("verified by")));
    QVERIFY(m_f->deviceBytes().mid(start).contains(QByteArray("\x02"
                                                              "28"))); // it was written
}

void TestSetupPage::invalid_formAndFileSayTheSame()
{
    // Issue 16: the form said "out of range" for "abc" where a file said "not a decimal integer".
    ui::ParameterField* field = page()->field(QStringLiteral("drive-power"));
    type(field, QStringLiteral("abc"));
    QVERIFY2(field->error().contains(QStringLiteral("'abc' is not a decimal integer")),
             qPrintable(field->error()));
    QVERIFY(!field->error().contains(QStringLiteral("out of range")));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("abc.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format":"stepdeck-parameters","version":1,"model":"elab",
                  "parameters":{"drive-power":"abc"}})");
    file.close();
    ParameterSet loaded;
    QString error;
    QVERIFY(!page()->readFile(path, &loaded, &error));
    // The same words after the name (the form names the field, the file its key).
    const QString reason = field->error().section(QStringLiteral(": "), 1, -1);
    QVERIFY2(error.endsWith(reason), qPrintable(error + QStringLiteral(" / ") + reason));
    // And a number outside the range is "out of range" in both.
    type(field, QStringLiteral("101"));
    QVERIFY2(field->error().contains(QStringLiteral("'101' is out of range")),
             qPrintable(field->error()));
}

void TestSetupPage::invalid_everyReasonListed_messageStaysOneLine()
{
    QWidget* line = page()->findChild<QWidget*>(QStringLiteral("setupMessage"));
    QVERIFY(line);
    const int height = line->sizeHint().height();
    QStringList names;
    const QStringList speeds{"start-speed", "max-speed", "acceleration", "feed-speed"};
    for (const QString& name : speeds) {
        for (Axis a : {Axis::X, Axis::Y}) {
            ui::ParameterField* field = page()->field(name, a);
            type(field, a == Axis::X ? QStringLiteral("abc") : QStringLiteral("99999999"));
            names << field->displayName();
        }
    }
    const QString text = page()->messageText();
    QVERIFY2(text.startsWith(QStringLiteral("Invalid values cannot be written (8): ")),
             qPrintable(text));
    for (const QString& name : names) // none cut off after the third
        QVERIFY2(text.contains(name + QStringLiteral(": ")), qPrintable(name));
    QCOMPARE(line->toolTip().count(QLatin1Char('\n')), 8); // one reason per line
    // One line high, whatever it says: the form above it does not move.
    QCOMPARE(line->sizeHint().height(), height);
    QCOMPARE(line->minimumSizeHint().height(), height);
    QVERIFY(!page()->write(false));
}

STEPDECK_TEST_MAIN(TestSetupPage)
#include "tst_setuppage.moc"
