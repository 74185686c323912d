#pragma once
#include "model/ModelInfo.h"

namespace stepdeck {

// The one explicit list of models (Registry.cpp, the only file that includes every model).
const QList<ModelInfo>& models();
const ModelInfo* findModel(const QString& id);
QStringList modelIds();
// "unknown controller model 'X' (known: elab, nanotec, ...)", translated.
QString unknownModelText(const QString& id);

} // namespace stepdeck
