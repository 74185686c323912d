#pragma once
#include <QLoggingCategory>

// The motion-program component (parser, check, runner): QT_LOGGING_RULES="stepdeck.program=true".
Q_DECLARE_LOGGING_CATEGORY(lcProgram)
