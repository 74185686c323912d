#pragma once
#include "controller/ControllerSession.h"
#include "machine/MachineDescription.h"

namespace stepdeck::ui {

// The connection bar's controller as a machine of one controller (issue 28, item 0: every
// connection is a machine): MachineDescription::singleController on the port, with the bus
// addresses (multi-drive models) and the reset line (models that have one) of spec.
//
// Each axis also takes what the window's former per-controller dialogs stored for this model
// (QSettings "units/…", "softLimits/…", "reference/…"), so that an operator's units, soft
// limits and referencing order carry over: units as mm or degrees (inches become mm), the
// limits converted, an axis without units in the controller's count. Nothing writes these
// keys any more; a machine's axes are edited in the machine editor (Edit machine…).
machine::MachineDescription connectionMachineOf(const ModelInfo& model, const ConnectionSpec& spec);

// Where program::MachineWorkOffsets keeps a connection machine's work origins: per model, as a
// machine file's are kept per file.
QString connectionOffsetsKey(const QString& modelId);

} // namespace stepdeck::ui
