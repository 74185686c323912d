#pragma once
#include "model/ParameterSchema.h"
#include <QCoreApplication>

namespace stepdeck::ui {

class ParameterField;

// What a setup write sends, from the form and what is known on the device (issue 11):
// - Readable values go out per field: changed from the value read or written, or set
//   explicitly where nothing is known. An unknown value (failed read) is never written, so
//   one silent drive does not turn a one-field edit into a write of everything.
// - Write-only values (E-LAB) go out as whole parameters (one command carries every axis)
//   whenever any axis is not known to be on the device -- after every reconnect, reset or
//   power cycle that is all of them.
// - Scope All sends every value the form has (unknown readable values excepted).
class WritePlan
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::WritePlan)
public:
    enum class Scope { Changed, All };

    static WritePlan build(const QList<ParameterField*>& fields, Scope scope);

    ParameterSet set;
    QStringList unknown; // readable values left out: not known, not set (display names)
    bool allKnownAndUnchanged = true; // every writable value written/read and unchanged
    // "Nothing to write: ..." -- why the set is empty.
    QString nothingToWriteText() const;
};

} // namespace stepdeck::ui
