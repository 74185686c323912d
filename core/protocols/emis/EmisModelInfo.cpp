// The registry entry of the SMC-IC4 (core/protocols/Registry.cpp).
#include "EmisController.h"
#include "EmisModel.h"
#include "EmisSimulator.h"

namespace stepdeck::emis {

ModelInfo modelInfo()
{
    ModelInfo info;
    info.id = QStringLiteral("emis");
    info.displayName = QStringLiteral("EMIS SMC-IC4 4-axis controller");
    info.line = lineSettings();
    info.capabilities = capabilities();
    info.schema = parameterSchema();
    info.presentation = presentation();
    return describeModel<EmisController, EmisSimulator>(std::move(info));
}

} // namespace stepdeck::emis
