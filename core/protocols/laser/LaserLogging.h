#pragma once
#include <QLoggingCategory>

namespace stepdeck::laser {

// This model's logging category, "stepdeck.laser" (QT_LOGGING_RULES="stepdeck.laser.*=true");
// defined in LaserModel.cpp and named by the model's descriptor (ModelInfo::logging).
Q_DECLARE_LOGGING_CATEGORY(lcLaser)

} // namespace stepdeck::laser
