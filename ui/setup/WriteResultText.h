#pragma once
#include "model/AxisNames.h"
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck::ui {

// What the setup page says after a successful write (issue 16): never more than the device
// confirmed. Write & verify reads back only what the protocol can report; a value it cannot
// (every E-LAB parameter) was written but not verified, and the text says so, as the CLI's
// `set` does ("written (the elab protocol cannot read these back)").
class WriteResultText
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::WriteResultText)
public:
    // set: what was written; verify: it was a Write & verify.
    // names: the controller's names of its axes.
    static QString success(const ParameterSchema& schema, const ParameterSet& set, bool verify,
                           const AxisNames& names = {});
    // Something in set can be read back, so a Write & verify verifies it (issue 31: a
    // write-only controller's "verifying" message would promise what it cannot do).
    static bool anyVerifiable(const ParameterSchema& schema, const ParameterSet& set);
    // "Max speed (X, Y, Z), Drive power": the parameters by their translated labels.
    static QString describe(const ParameterSchema& schema, const ParameterSet& set,
                            const AxisNames& names = {});
};

} // namespace stepdeck::ui
