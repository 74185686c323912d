#include "ParameterFile.h"
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSaveFile>
#include <cerrno>

namespace stepdeck {

ParameterFile::Status ParameterFile::save(const ParameterSchema& schema, const QString& modelId,
                                          const ParameterSet& set, const QString& path,
                                          QString* error, const QJsonObject& extra)
{
    QJsonObject json = schema.toJson(modelId, set);
    for (auto it = extra.constBegin(); it != extra.constEnd(); ++it)
        json.insert(it.key(), it.value());
    const QByteArray bytes = QJsonDocument(json).toJson(QJsonDocument::Indented);
    QSaveFile file(path);
    // Unbuffered, and the count checked: Qt 6.4 reports a short write (disk full, file size
    // limit) only as a smaller count, and a buffered QSaveFile drops the rest silently when
    // it flushes, so commit() would replace the old file with a truncated one.
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return Status::FileError;
    }
    errno = 0;
    if (file.write(bytes) != bytes.size()) {
        // The reason of the failed write(2) (EFBIG, ENOSPC), before cancelWriting() replaces
        // the file's error with its own.
        const QString why =
            file.error() != QFileDevice::NoError ? file.errorString() : qt_error_string(errno);
        file.cancelWriting();
        file.commit(); // removes the temporary file; the old file stays as it was
        *error = tr("Cannot write %1: %2").arg(path, why);
        return Status::FileError;
    }
    if (!file.commit()) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return Status::FileError;
    }
    return Status::Ok;
}

ParameterFile::Status ParameterFile::load(const ParameterSchema& schema, const QString& modelId,
                                          const QList<Axis>& axes, const QString& path,
                                          ParameterSet* set, QString* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = tr("Cannot open %1: %2").arg(path, file.errorString());
        return Status::FileError;
    }
    const QByteArray text = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        *error = tr("Cannot open %1: %2").arg(path, file.errorString());
        return Status::FileError;
    }
    if (text.trimmed().isEmpty()) {
        // Qt calls this "line 1, column 1: illegal value": say what is wrong in plain words.
        *error =
            tr("%1 is empty: a StepDeck parameter file holds a JSON object with the parameters")
                .arg(QFileInfo(path).fileName());
        return Status::NotJson;
    }
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
        return Status::NotJson;
    }
    if (!doc.isObject()) {
        *error = tr("%1 is not a parameter file: it holds no JSON object").arg(path);
        return Status::NotJson;
    }
    QString why;
    ParameterSet parsed;
    if (!schema.fromJson(doc.object(), modelId, axes, &parsed, &why)) {
        *error = tr("%1: %2").arg(QFileInfo(path).fileName(), why);
        return Status::Invalid;
    }
    *set = parsed;
    return Status::Ok;
}

} // namespace stepdeck
