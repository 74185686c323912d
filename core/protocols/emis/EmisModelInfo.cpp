// The registry entry of the SMC-IC4 (core/protocols/Registry.cpp).
#include "EmisController.h"
#include "EmisModel.h"
#include "EmisSimulator.h"

namespace stepdeck::emis {

namespace {
// The registry's display name, shown through QCoreApplication::translate("Models", ...).
const char* const kDisplayName = QT_TRANSLATE_NOOP("Models", "EMIS SMC-IC4 4-axis controller");
} // namespace

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("emis");
    info.displayName = QString::fromLatin1(kDisplayName);
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = parameterSchema();
    info.createController = [](Transport* transport, const ControllerOptions& options) {
        return static_cast<Controller*>(new EmisController(transport, options));
    };
    info.createSimulator = [](const SimulatorOptions& options) {
        return static_cast<Simulator*>(new EmisSimulator(options));
    };
    info.presentation = presentation();
    return info;
}

} // namespace stepdeck::emis
