#include "WriteResultText.h"

namespace stepdeck::ui {

QString WriteResultText::describe(const ParameterSchema& schema, const ParameterSet& set,
                                  const AxisNames& names)
{
    QStringList parts;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = schema.find(it.key());
        const QString label = spec ? ParameterSchema::displayLabel(*spec) : it.key();
        QStringList axes;
        for (auto a = it.value().perAxis.cbegin(); a != it.value().perAxis.cend(); ++a)
            axes << names.name(a.key());
        parts << (axes.isEmpty()
                      ? label
                      : QStringLiteral("%1 (%2)").arg(label, axes.join(QStringLiteral(", "))));
    }
    return parts.join(QStringLiteral(", "));
}

bool WriteResultText::anyVerifiable(const ParameterSchema& schema, const ParameterSet& set)
{
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = schema.find(it.key());
        if (spec && spec->readable)
            return true;
    }
    return false;
}

QString WriteResultText::success(const ParameterSchema& schema, const ParameterSet& set,
                                 bool verify, const AxisNames& names)
{
    if (!verify)
        return tr("Written: %1.").arg(describe(schema, set, names));
    ParameterSet readBack;
    ParameterSet writeOnly;
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = schema.find(it.key());
        (spec && spec->readable ? readBack : writeOnly).insert(it.key(), it.value());
    }
    if (readBack.isEmpty())
        return tr("Written: %1. Nothing could be verified: this controller cannot read these "
                  "values back.")
            .arg(describe(schema, writeOnly, names));
    if (writeOnly.isEmpty())
        return tr("Written and verified by reading back: %1.")
            .arg(describe(schema, readBack, names));
    return tr("Written and verified by reading back: %1. Written but not verified (this "
              "controller cannot read them back): %2.")
        .arg(describe(schema, readBack, names), describe(schema, writeOnly, names));
}

} // namespace stepdeck::ui
