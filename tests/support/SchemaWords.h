#pragma once
// Schema words and their German translation (docs/architecture.md, Translations): every word a
// model's parameter table writes (label, group, unit, word choices, description, warning) has
// a finished translation in translations/stepdeck_de.ts. Shared by tst_translations and
// tst_modelcompleteness.
#include "model/ModelInfo.h"
#include <QFile>
#include <QSet>
#include <QXmlStreamReader>

namespace stepdeck::test {

// Sources with a finished German translation in the schema words' context.
inline QSet<QString> translatedSchemaWords(const QString& tsPath)
{
    QSet<QString> out;
    QFile file(tsPath);
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
            if (context == QLatin1String(ParameterSchema::kTranslationContext) && !unfinished &&
                !text.isEmpty())
                out.insert(source);
        }
    }
    return out;
}

// The model's schema words (numeric choices excepted) that have no finished translation, as
// "model/key: word".
inline QStringList untranslatedSchemaWords(const ModelInfo& model, const QSet<QString>& translated)
{
    QStringList missing;
    for (const ParameterSpec& spec : model.schema.specs()) {
        QStringList words{spec.group, spec.label, spec.unit, spec.description, spec.warning};
        for (const QString& choice : spec.choices) {
            bool number = false;
            choice.toDouble(&number);
            if (!number)
                words << choice;
        }
        for (const QString& w : std::as_const(words)) {
            if (!w.isEmpty() && !translated.contains(w))
                missing << QStringLiteral("%1/%2: %3").arg(model.id, spec.name, w);
        }
    }
    return missing;
}

} // namespace stepdeck::test
