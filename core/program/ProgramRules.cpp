#include "ProgramRules.h"

namespace stepdeck::program {

QString ProgramRules::parameterWrite(const ParameterSchema& schema, const Capabilities& caps,
                                     const ParameterRules& modelRules, const ParameterSet& set,
                                     const ParameterSet& known)
{
    if (modelRules)
        return modelRules(schema, set, known);
    return schema.validate(set, caps.axes);
}

QString ProgramRules::setupIncomplete(const ParameterSchema& schema,
                                      const QStringList& setupBeforeMotion, bool incomplete)
{
    if (!incomplete)
        return {};
    QStringList labels;
    for (const QString& name : setupBeforeMotion)
        labels << schema.displayLabel(name);
    return tr("its setup is incomplete, so it refuses every move: write %1 on the Setup page "
              "first")
        .arg(labels.join(QStringLiteral(", ")));
}

} // namespace stepdeck::program
