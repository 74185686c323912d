#include "ProgramRules.h"
#include "FeedLimit.h"
#include <algorithm>

namespace stepdeck::program {

ParameterSet ProgramRules::feedRateWrite(const machine::MachineDescription& description,
                                         const QString& controller, const Capabilities& caps,
                                         const ProgramBlock& block, const ParameterSet& known,
                                         const ParameterSpec* rateSpec)
{
    if (!caps.feedRateParameter || !block.feed || block.kind != BlockKind::Feed)
        return {};
    const QString name = QString::fromLatin1(caps.feedRateParameter);
    ParameterValue rate;
    qint64 slowest = 0;
    for (auto it = block.axes.cbegin(); it != block.axes.cend(); ++it) {
        const machine::MachineAxis* a = description.axis(it.key());
        if (!a || a->controller != controller)
            continue;
        const qint64 r = FeedLimit::axisRate(description, *a, caps, rateSpec, known, block).runs;
        if (r == 0)
            continue; // G93 on an axis that does not move: no rate
        rate.perAxis.insert(a->axis, r);
        slowest = slowest == 0 ? r : std::min(slowest, r);
    }
    if (rate.perAxis.isEmpty())
        return {};
    if (caps.feedRateWholeSet) {
        const ParameterValue held = known.value(name);
        for (Axis axis : caps.axes) {
            if (rate.perAxis.contains(axis))
                continue;
            rate.perAxis.insert(axis, held.perAxis.contains(axis) ? held.perAxis.value(axis)
                                                                  : QVariant(slowest));
        }
    }
    return {{name, rate}};
}

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
