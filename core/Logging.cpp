#include "Logging.h"

Q_LOGGING_CATEGORY(lcTransport, "stepdeck.transport", QtWarningMsg)
Q_LOGGING_CATEGORY(lcController, "stepdeck.controller", QtWarningMsg)
Q_LOGGING_CATEGORY(lcPoller, "stepdeck.poller", QtWarningMsg)
Q_LOGGING_CATEGORY(lcJog, "stepdeck.jog", QtWarningMsg)
Q_LOGGING_CATEGORY(lcSession, "stepdeck.session", QtWarningMsg)
Q_LOGGING_CATEGORY(lcBridge, "stepdeck.bridge", QtWarningMsg)
Q_LOGGING_CATEGORY(lcSimulator, "stepdeck.simulator", QtWarningMsg)
Q_LOGGING_CATEGORY(lcMotion, "stepdeck.motion", QtWarningMsg)
