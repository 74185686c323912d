#pragma once
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck {

// The one place that reads and writes parameter files (the JSON format of
// ParameterSchema::toJson/fromJson), for the GUI's setup pages and the CLI's export/import.
// Errors are one sentence naming the file and the cause; a broken JSON file is located by
// line and column, the way an editor shows it.
class ParameterFile
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ParameterFile)
public:
    enum class Status {
        Ok,
        FileError, // the file cannot be opened, read or written
        NotJson,   // not JSON, or no JSON object at its top
        Invalid,   // JSON, but not a valid parameter set for this model and machine
    };

    // Writes atomically (QSaveFile): the file appears complete or not at all, and a failed
    // write leaves an existing file as it was. `extra` adds top-level keys (the CLI's
    // "origin"); fromJson ignores unknown top-level keys.
    static Status save(const ParameterSchema& schema, const QString& modelId,
                       const ParameterSet& set, const QString& path, QString* error,
                       const QJsonObject& extra = {});
    // Parses and validates everything before returning anything: on an error *set is
    // left untouched.
    static Status load(const ParameterSchema& schema, const QString& modelId,
                       const QList<Axis>& axes, const QString& path, ParameterSet* set,
                       QString* error);
};

} // namespace stepdeck
