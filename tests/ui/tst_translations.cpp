// Languages: the German catalogue is complete, and once installed it translates the widgets,
// the model's parameter labels and core messages (tr() of Q_DECLARE_TR_FUNCTIONS classes and
// codec texts included: lupdate files each string under its run-time context).
#include "SchemaWords.h"
#include "TestMain.h"
#include "UiTestSupport.h"
#include "model/ParameterFile.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabCtlParameters.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/nanotec/NanotecCodec.h"
#include "safety/SafetyBar.h"
#include "setup/ParameterField.h"
#include "window/Translations.h"
#include <QComboBox>
#include <QPushButton>
#include <QXmlStreamReader>

using namespace stepdeck;
using namespace stepdeck::test;

class TestTranslations : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void germanCatalogue_everyMessageTranslated();
    void effective_configuredOrSystem_data();
    void effective_configuredOrSystem();
    void german_installed_translatesUiSchemaAndCore_data();
    void german_installed_translatesUiSchemaAndCore();
    void german_coreMessagesAtRunTime();
    void german_mainWindow_showsGermanLabels();
    void german_polarity_labelsGermanValuesKept();
    void german_schemaWords_everyOneTranslated();
    void german_validationMessages_nameLabelsNotKeys_data();
    void german_validationMessages_nameLabelsNotKeys();
    void german_elabRules_nameLabelsNotKeys();
    void german_typedOrFiledNames_keepTheKey();
    void english_afterGerman_noGermanLeftPluralsSpelledOut();
};

namespace {
QSet<QString> translatedSchemaWords()
{
    return test::translatedSchemaWords(
        QStringLiteral(STEPDECK_SOURCE_DIR "/translations/stepdeck_de.ts"));
}

// The schema keys (kebab-case names) a message quotes.
QStringList keysIn(const ParameterSchema& schema, const QString& message)
{
    QStringList keys;
    for (const ParameterSpec& spec : schema.specs()) {
        if (spec.name.contains(QLatin1Char('-')) && message.contains(spec.name))
            keys << spec.name;
    }
    return keys;
}
} // namespace

void TestTranslations::germanCatalogue_everyMessageTranslated()
{
    QFile file(QStringLiteral(STEPDECK_SOURCE_DIR "/translations/stepdeck_de.ts"));
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    QXmlStreamReader xml(&file);
    QString source;
    int messages = 0;
    QStringList missing;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            ++messages;
            const bool unfinished =
                xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (unfinished || text.trimmed().isEmpty())
                missing << source;
        }
    }
    QVERIFY(!xml.hasError());
    QVERIFY(messages > 100);
    QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QStringLiteral(" | "))));
}

void TestTranslations::effective_configuredOrSystem_data()
{
    QTest::addColumn<QString>("configured");
    QTest::addColumn<QString>("expected");
    QTest::newRow("german chosen") << QStringLiteral("de") << QStringLiteral("de");
    QTest::newRow("english chosen") << QStringLiteral("en") << QStringLiteral("en");
    const QString system = QLocale::system().name().left(2);
    QTest::newRow("system") << QString()
                            << (system == QLatin1String("de") ? QStringLiteral("de")
                                                              : QStringLiteral("en"));
}

void TestTranslations::effective_configuredOrSystem()
{
    QFETCH(QString, configured);
    QFETCH(QString, expected);
    QCOMPARE(ui::translations::effective(configured), expected);
}

void TestTranslations::german_installed_translatesUiSchemaAndCore_data()
{
    QTest::addColumn<QString>("context");
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("german");
    QTest::newRow("widget") << "stepdeck::ui::SafetyBar"
                            << "STOP  (Esc)"
                            << "STOPP  (Esc)";
    QTest::newRow("parameter label") << "Parameters"
                                     << "Start speed"
                                     << "Startgeschwindigkeit";
    QTest::newRow("status bit") << "stepdeck::elab::Presentation"
                                << "The motors are powered."
                                << "Die Motoren sind bestromt.";
    QTest::newRow("core controller") << "stepdeck::Controller"
                                     << "jog refused: not connected"
                                     << "Tippbetrieb abgelehnt: nicht verbunden";
    QTest::newRow("core Q_DECLARE_TR_FUNCTIONS") << "stepdeck::ParameterSchema"
                                                 << "unknown parameter '%1'"
                                                 << "unbekannter Parameter '%1'";
    QTest::newRow("codec context") << "stepdeck::elab::Codec"
                                   << "unexpected control byte"
                                   << "unerwartetes Steuerzeichen";
}

void TestTranslations::german_installed_translatesUiSchemaAndCore()
{
    QFETCH(QString, context);
    QFETCH(QString, source);
    QFETCH(QString, german);
    static const QString lang = ui::translations::install(qApp, QStringLiteral("de"));
    QCOMPARE(lang, QStringLiteral("de"));
    QCOMPARE(QCoreApplication::translate(context.toUtf8().constData(), source.toUtf8().constData()),
             german);
}

// The messages as core code builds them, with the German catalogue installed: the contexts
// the code uses at run time are the ones lupdate filed the strings under.
void TestTranslations::german_coreMessagesAtRunTime()
{
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("de")), QStringLiteral("de"));
    const ParameterSchema schema = elab::parameterSchema();
    ParameterSet set;
    set[QStringLiteral("warp-speed")].global = qint64(1);
    QCOMPARE(schema.validate(set, {Axis::X, Axis::Y, Axis::Z}),
             QStringLiteral("unbekannter Parameter 'warp-speed'"));

    QString error;
    ParameterSet loaded;
    QCOMPARE(ParameterFile::load(schema, QStringLiteral("elab"), {Axis::X},
                                 QStringLiteral("/nonexistent/p.json"), &loaded, &error),
             ParameterFile::Status::FileError);
    QVERIFY2(error.startsWith(QStringLiteral("/nonexistent/p.json kann nicht geöffnet werden: ")),
             qPrintable(error));

    QCOMPARE(nanotec::forbiddenReason("@A"),
             QStringLiteral("'@A' wird nie gesendet: es startet den Bootloader (Handbuch 5.32)"));

    elab::ReplyDecoder decoder;
    QStringList errors;
    for (const elab::Reply& reply : decoder.feed(QByteArray("xyz\x06")))
        errors << reply.error;
    QVERIFY2(errors.contains(QStringLiteral("Bytes außerhalb einer Antwort")),
             qPrintable(errors.join(QStringLiteral(" | "))));
}

void TestTranslations::german_mainWindow_showsGermanLabels()
{
    ui::translations::install(qApp, QStringLiteral("de"));
    UiFixture f;
    QCOMPARE(f.window->safetyBar()->stopButton()->text(), QStringLiteral("STOPP  (Esc)"));
    QCOMPARE(f.window->safetyBar()->panicButton()->text(), QStringLiteral("PANIK  (F1)"));
}

void TestTranslations::german_polarity_labelsGermanValuesKept()
{
    // Issue 11: the polarity choices read German; the value (and the file format) keeps
    // low/high.
    ui::translations::install(qApp, QStringLiteral("de"));
    const ParameterSchema schema = findModel(QStringLiteral("elab"))->schema;
    const ParameterSpec* spec = schema.find(QStringLiteral("limit-polarity"));
    QVERIFY(spec);
    ui::ParameterField field(schema, *spec, Axis::X);
    auto* combo = qobject_cast<QComboBox*>(field.editor());
    QVERIFY(combo);
    QStringList labels;
    for (int i = 0; i < combo->count(); ++i)
        labels << combo->itemText(i);
    QCOMPARE(labels, (QStringList{QStringLiteral("High-aktiv"), QStringLiteral("Low-aktiv")}));
    field.setValue(QStringLiteral("low"), true);
    QCOMPARE(combo->currentText(), QStringLiteral("Low-aktiv"));
    QCOMPARE(field.value().toString(), QStringLiteral("low"));
    combo->setCurrentIndex(0);
    QCOMPARE(field.value().toString(), QStringLiteral("high"));

    // The file format keeps the values.
    ParameterSet set;
    set[spec->name].perAxis = {{Axis::X, field.value()}, {Axis::Y, QStringLiteral("low")}};
    const QJsonObject perAxis = schema.toJson(QStringLiteral("elab"), set)
                                    .value(QStringLiteral("parameters"))
                                    .toObject()
                                    .value(spec->name)
                                    .toObject();
    QCOMPARE(perAxis.value(QStringLiteral("X")).toString(), QStringLiteral("high"));
    QCOMPARE(perAxis.value(QStringLiteral("Y")).toString(), QStringLiteral("low"));
}

// Issue 10: the schema tables mark their words with QT_TRANSLATE_NOOP; every word of every
// model (numbers excepted) has a German translation, so no setup page shows English.
void TestTranslations::german_schemaWords_everyOneTranslated()
{
    const QSet<QString> translated = translatedSchemaWords();
    QVERIFY(translated.size() > 200);
    QStringList missing;
    for (const ModelInfo& model : models())
        missing << test::untranslatedSchemaWords(model, translated);
    QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QStringLiteral(" | "))));
}

void TestTranslations::german_validationMessages_nameLabelsNotKeys_data()
{
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("expected");
    QTest::newRow("elab") << "elab"
                          << "max-speed"
                          << "Maximalgeschwindigkeit: Wert '70000' liegt außerhalb des Bereichs "
                             "(erlaubt: 0..65535 Schritte/s) (X)";
    QTest::newRow("nanotec") << "nanotec"
                             << "phase-current"
                             << "Phasenstrom: Wert '70000' liegt außerhalb des Bereichs "
                                "(erlaubt: 0..150 %) (X)";
    QTest::newRow("emis") << "emis"
                          << "reference-speed"
                          << "Referenzgeschwindigkeit: Wert '70000' liegt außerhalb des Bereichs "
                             "(erlaubt: 1..65535 Schritte/s)";
}

// Issue 11: a refusal on the German screen names the parameter as the form does (its label,
// with the unit translated), not by its file key.
void TestTranslations::german_validationMessages_nameLabelsNotKeys()
{
    QFETCH(QString, model);
    QFETCH(QString, name);
    QFETCH(QString, expected);
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("de")), QStringLiteral("de"));
    const ModelInfo* info = findModel(model);
    QVERIFY(info);
    const ParameterSpec* spec = info->schema.find(name);
    QVERIFY(spec);
    ParameterSet set;
    if (spec->perAxis)
        set[name].perAxis.insert(Axis::X, qint64(70000));
    else
        set[name].global = qint64(70000);
    const QString message = info->schema.validate(set, info->capabilities.axes);
    QCOMPARE(message, expected);
    QVERIFY2(keysIn(info->schema, message).isEmpty(), qPrintable(message));
}

void TestTranslations::german_elabRules_nameLabelsNotKeys()
{
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("de")), QStringLiteral("de"));
    const ParameterSchema schema = elab::parameterSchema();
    ParameterSet set;
    for (const char* name : {"start-speed", "feed-speed"}) {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            set[QLatin1String(name)].perAxis.insert(a, qint64(100));
    }
    set[QStringLiteral("feed-speed")].perAxis[Axis::X] = qint64(150);
    QList<elab::ElabParameterWrite> plan;
    const QString feed = elab::ElabCtlParameters::plan(schema, set, {}, &plan);
    QCOMPARE(feed,
             QStringLiteral("Vorschubgeschwindigkeit 150 auf Achse X muss unter "
                            "Startgeschwindigkeit 100 liegen (der Vorschub hat keine Rampe)"));
    const QString setup = elab::ElabCtlParameters::setupIncompleteHint();
    QCOMPARE(setup, QStringLiteral("zuerst Startgeschwindigkeit, Maximalgeschwindigkeit und "
                                   "Beschleunigung schreiben"));
    QVERIFY(keysIn(schema, feed + setup).isEmpty());
}

// Where the user typed the key (NAME=VALUE) or the file holds it, the message names the key.
void TestTranslations::german_typedOrFiledNames_keepTheKey()
{
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("de")), QStringLiteral("de"));
    const ParameterSchema schema = elab::parameterSchema();
    QString name, error;
    ParameterValue value;
    QVERIFY(!schema.parseAssignment(QStringLiteral("drive-power=101"), {Axis::X}, &name, &value,
                                    &error));
    QCOMPARE(error, QStringLiteral("drive-power: Wert '101' liegt außerhalb des Bereichs "
                                   "(erlaubt: 0..100 %)"));
    const QJsonObject file{{"format", "stepdeck-parameters"},
                           {"version", 1},
                           {"model", "elab"},
                           {"parameters", QJsonObject{{"drive-power", 101}}}};
    ParameterSet set;
    QVERIFY(!schema.fromJson(file, QStringLiteral("elab"), {Axis::X}, &set, &error));
    QVERIFY2(error.startsWith(QStringLiteral("drive-power: Wert '101'")), qPrintable(error));
}

// Switching back to English takes the German catalogue out (a test's rows after a German row
// ran in German), and English reads its plural forms: "2 errors", not "2 error(s)".
void TestTranslations::english_afterGerman_noGermanLeftPluralsSpelledOut()
{
    const char* context = "stepdeck::ui::ProgramErrorList";
    const char* plural = "%n error(s); click one to go to its line.";
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("de")), QStringLiteral("de"));
    QCOMPARE(QCoreApplication::translate("stepdeck::ui::MachineGoTo", "Go to"),
             QStringLiteral("Anfahren"));
    QCOMPARE(ui::translations::install(qApp, QStringLiteral("en")), QStringLiteral("en"));
    QCOMPARE(QCoreApplication::translate("stepdeck::ui::MachineGoTo", "Go to"),
             QStringLiteral("Go to"));
    QCOMPARE(QCoreApplication::translate(context, plural, nullptr, 2),
             QStringLiteral("2 errors; click one to go to its line."));
    QCOMPARE(QCoreApplication::translate(context, plural, nullptr, 1),
             QStringLiteral("1 error; click it to go to its line."));
}

STEPDECK_TEST_MAIN(TestTranslations)
#include "tst_translations.moc"
