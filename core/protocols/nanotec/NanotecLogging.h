#pragma once
#include <QLoggingCategory>

namespace stepdeck::nanotec {

// This model's logging category, "stepdeck.nanotec" (QT_LOGGING_RULES="stepdeck.nanotec.*=true");
// defined in NanotecModel.cpp and named by the model's descriptor (ModelInfo::logging).
Q_DECLARE_LOGGING_CATEGORY(lcNanotec)

} // namespace stepdeck::nanotec
