#pragma once
#include <QLoggingCategory>

namespace stepdeck::emis {

// This model's logging category, "stepdeck.emis" (QT_LOGGING_RULES="stepdeck.emis.*=true"); defined
// in EmisModel.cpp and named by the model's descriptor (ModelInfo::logging).
Q_DECLARE_LOGGING_CATEGORY(lcEmis)

} // namespace stepdeck::emis
