#pragma once
#include "controller/ControllerOptions.h"
#include "model/Capabilities.h"
#include "model/LineSettings.h"
#include "model/ModelPresentation.h"
#include "model/ParameterSchema.h"
#include "sim/Simulator.h"
#include <functional>

namespace stepdeck {

class Controller;
class Transport;

// Everything the application knows about one controller model. Adding a model means its
// folder under core/protocols/<model>/ plus one line in Registry.cpp.
struct ModelInfo
{
    QString id;          // "elab", "nanotec", ...
    QString displayName; // "E-LAB 3-axis stepper controller"
    LineSettings line;
    Capabilities capabilities;
    ParameterSchema schema;
    std::function<Controller*(Transport*, const ControllerOptions&)> createController;
    std::function<Simulator*(const SimulatorOptions&)> createSimulator;
    // How the UI shows this model's raw words and traffic (optional members; see
    // model/ModelPresentation.h). The UI never interprets bytes itself.
    ModelPresentation presentation;
};

const QList<ModelInfo>& models();
const ModelInfo* findModel(const QString& id);
QStringList modelIds();

} // namespace stepdeck
