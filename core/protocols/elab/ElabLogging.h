#pragma once
#include <QLoggingCategory>

namespace stepdeck::elab {

// This model's logging category, "stepdeck.elab" (QT_LOGGING_RULES="stepdeck.elab.*=true"); defined
// in ElabModel.cpp and named by the model's descriptor (ModelInfo::logging).
Q_DECLARE_LOGGING_CATEGORY(lcElab)

} // namespace stepdeck::elab
