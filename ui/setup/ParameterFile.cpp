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
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (!doc.isObject()) {
        *error = tr("%1 is not a parameter file: %2").arg(path, parseError.errorString());
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
