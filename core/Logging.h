#pragma once
#include <QLoggingCategory>

// One logging category per generic core component (each model declares its own in its
// folder, <Model>Logging.h); enable with QT_LOGGING_RULES="stepdeck.*=true".
Q_DECLARE_LOGGING_CATEGORY(lcTransport)
Q_DECLARE_LOGGING_CATEGORY(lcController)
Q_DECLARE_LOGGING_CATEGORY(lcPoller)
Q_DECLARE_LOGGING_CATEGORY(lcJog)
Q_DECLARE_LOGGING_CATEGORY(lcSession)
Q_DECLARE_LOGGING_CATEGORY(lcBridge)
Q_DECLARE_LOGGING_CATEGORY(lcSimulator)
Q_DECLARE_LOGGING_CATEGORY(lcMotion)
