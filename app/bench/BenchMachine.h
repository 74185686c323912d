#pragma once
#include "machine/Machine.h"

namespace stepdeck::bench {

// The benches' machine of one controller "table" (model `modelId` on `port`): `axes` in mm at
// `stepsPerMm`, created, opened and connected (Idle); false with *error otherwise.
bool openTable(machine::Machine& m, const QString& name, const QString& modelId,
               const QString& port, const QList<Axis>& axes, double stepsPerMm, QString* error);

} // namespace stepdeck::bench
