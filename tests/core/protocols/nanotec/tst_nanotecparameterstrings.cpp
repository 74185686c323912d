// The Nanotec schema's words are data; the UI translates them through the "Parameters"
// context. NanotecParameterStrings.cpp lists them for lupdate: every string the schema holds
// must be in the German catalogue there, translated, or the setup page shows English.
#include "protocols/nanotec/NanotecSchema.h"
#include <QFile>
#include <QSet>
#include <QXmlStreamReader>
#include <QtTest>

using namespace stepdeck;

class TestNanotecParameterStrings : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void schemaStrings_allTranslatedInGerman();
};

namespace {
// Sources with a finished translation in the "Parameters" context of the .ts file.
QSet<QString> translatedParameterStrings(const QString& path)
{
    QSet<QString> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return out;
    QXmlStreamReader xml(&file);
    QString context, source;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
        } else if (xml.name() == QLatin1String("translation")) {
            const bool unfinished =
                xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished");
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (context == QLatin1String("Parameters") && !unfinished && !text.isEmpty())
                out.insert(source);
        }
    }
    return out;
}
} // namespace

void TestNanotecParameterStrings::schemaStrings_allTranslatedInGerman()
{
    const QSet<QString> translated = translatedParameterStrings(
        QStringLiteral(STEPDECK_SOURCE_DIR "/translations/stepdeck_de.ts"));
    QVERIFY(translated.size() > 100);
    QStringList missing;
    const ParameterSchema schema = nanotec::parameterSchema();
    for (const ParameterSpec& spec : schema.specs()) {
        QStringList words{spec.group, spec.label, spec.unit, spec.description, spec.warning};
        words << spec.choices;
        for (const QString& w : std::as_const(words))
            if (!w.isEmpty() && !translated.contains(w) && !missing.contains(w))
                missing << w;
    }
    QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QStringLiteral(" | "))));
}

QTEST_GUILESS_MAIN(TestNanotecParameterStrings)
#include "tst_nanotecparameterstrings.moc"
