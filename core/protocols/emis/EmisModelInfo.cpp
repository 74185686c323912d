// The registry entry of the SMC-IC4 (core/protocols/Registry.cpp).
#include "EmisController.h"
#include "EmisLogging.h"
#include "EmisModel.h"
#include "EmisSimulator.h"

namespace stepdeck::emis {

namespace {
// The registry's display name, shown through QCoreApplication::translate("Models", ...).
const char* const kDisplayName = QT_TRANSLATE_NOOP("Models", "EMIS SMC-IC4 4-axis controller");
} // namespace
Q_LOGGING_CATEGORY(lcEmis, "stepdeck.emis", QtWarningMsg)

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("emis");
    info.displayName = QString::fromLatin1(kDisplayName);
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = parameterSchema();
    info.scenario = scenarioSupport();
    info.soak = soakProfile();
    info.presentation = presentation();
    info.logging = &lcEmis;
    return describeModel<EmisController, EmisSimulator>(std::move(info));
}

} // namespace stepdeck::emis
