#include "ParameterFile.h"
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>

namespace stepdeck::ui {

bool ParameterFile::save(const ParameterSchema& schema, const QString& modelId,
                         const ParameterSet& set, const QString& path, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    if (file.write(QJsonDocument(schema.toJson(modelId, set)).toJson()) < 0) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

bool ParameterFile::load(const ParameterSchema& schema, const QString& modelId,
                         const QList<Axis>& axes, const QString& path, ParameterSet* set,
                         QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = tr("Cannot open %1: %2").arg(path, file.errorString());
        return false;
    }
    const QByteArray text = file.readAll();
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Where the technician has to look: line and column (both from 1), not an offset.
        const QByteArray before = text.left(parseError.offset);
        const int line = int(before.count('\n')) + 1;
        const QString lastLine = QString::fromUtf8(before.mid(before.lastIndexOf('\n') + 1));
        const int column = int(lastLine.size()) + 1; // characters, not UTF-8 bytes
        *error = tr("%1, line %2, column %3: %4")
                     .arg(QFileInfo(path).fileName())
                     .arg(line)
                     .arg(column)
                     .arg(parseError.errorString());
        return false;
    }
    if (!doc.isObject()) {
        *error = tr("%1 is not a parameter file: it holds no JSON object").arg(path);
        return false;
    }
    QString why;
    if (!schema.fromJson(doc.object(), modelId, axes, set, &why)) {
        *error = tr("%1: %2").arg(QFileInfo(path).fileName(), why);
        return false;
    }
    return true;
}

} // namespace stepdeck::ui
