#pragma once
#include <QLoggingCategory>

// One logging category per core component; enable with QT_LOGGING_RULES="stepdeck.*=true".
Q_DECLARE_LOGGING_CATEGORY(lcTransport)
Q_DECLARE_LOGGING_CATEGORY(lcController)
Q_DECLARE_LOGGING_CATEGORY(lcPoller)
Q_DECLARE_LOGGING_CATEGORY(lcJog)
Q_DECLARE_LOGGING_CATEGORY(lcSession)
Q_DECLARE_LOGGING_CATEGORY(lcSimulator)
Q_DECLARE_LOGGING_CATEGORY(lcElab)
Q_DECLARE_LOGGING_CATEGORY(lcNanotec)
Q_DECLARE_LOGGING_CATEGORY(lcEmis)
