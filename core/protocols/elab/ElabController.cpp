#include "ElabController.h"
#include "ElabModel.h"

namespace stepdeck::elab {

ElabController::ElabController(Transport* transport, const ControllerOptions& options,
                               QObject* parent)
    : Controller(transport, options, parent)
{
}

Capabilities ElabController::capabilities() const { return elab::capabilities(); }
ParameterSchema ElabController::schema() const { return elab::parameterSchema(); }

} // namespace stepdeck::elab
