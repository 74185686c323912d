#pragma once
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck::ui {

// Parameter files in the CLI's JSON format (ParameterSchema::toJson/fromJson), with errors
// that name the file and the cause.
class ParameterFile
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::ParameterFile)
public:
    static bool save(const ParameterSchema& schema, const QString& modelId, const ParameterSet& set,
                     const QString& path, QString* error);
    // Parses and validates everything before returning anything.
    static bool load(const ParameterSchema& schema, const QString& modelId, const QList<Axis>& axes,
                     const QString& path, ParameterSet* set, QString* error);
};

} // namespace stepdeck::ui
