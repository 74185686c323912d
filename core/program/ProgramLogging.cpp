#include "ProgramLogging.h"

Q_LOGGING_CATEGORY(lcProgram, "stepdeck.program", QtWarningMsg)
