#include "WritePlan.h"
#include "setup/ParameterField.h"

namespace stepdeck::ui {

namespace {
void put(ParameterSet& set, const ParameterField* f)
{
    ParameterValue& v = set[f->spec().name];
    if (f->axis())
        v.perAxis.insert(*f->axis(), f->value());
    else
        v.global = f->value();
}
} // namespace

WritePlan WritePlan::build(const QList<ParameterField*>& fields, Scope scope)
{
    WritePlan plan;
    QSet<QString> writeOnlyDue; // write-only parameters with an axis not known on the device
    for (const ParameterField* f : fields) {
        if (!f->spec().writable)
            continue;
        const bool known = f->baseline().isValid();
        if (!known || f->isChanged())
            plan.allKnownAndUnchanged = false;
        if (f->spec().readable) {
            if (!f->value().isValid()) {
                plan.unknown << f->displayName();
                continue;
            }
            if (scope == Scope::All || f->isChanged())
                put(plan.set, f);
        } else if (scope == Scope::All || f->isChanged()) {
            writeOnlyDue.insert(f->spec().name);
        }
    }
    for (const ParameterField* f : fields) {
        if (f->spec().writable && !f->spec().readable && writeOnlyDue.contains(f->spec().name))
            put(plan.set, f); // the whole parameter: every axis in one command
    }
    return plan;
}

QString WritePlan::nothingToWriteText() const
{
    if (allKnownAndUnchanged)
        return tr("Nothing to write: every value was written or read in this session and "
                  "nothing changed since.");
    if (!unknown.isEmpty()) {
        QStringList names = unknown.mid(0, 4);
        if (unknown.size() > 4)
            names << QStringLiteral("\u2026");
        return tr("Nothing to write: %n value(s) could not be read (%1); they are written "
                  "only once you set them.",
                  nullptr, int(unknown.size()))
            .arg(names.join(QStringLiteral(", ")));
    }
    return tr("Nothing to write: every field matches the controller.");
}

} // namespace stepdeck::ui
