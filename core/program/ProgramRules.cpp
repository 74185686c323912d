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

namespace {
const ParameterSpec* spindleSpec(const Capabilities& caps, const ParameterSchema& schema)
{
    return caps.spindleSpeedParameter ? schema.find(QString::fromLatin1(caps.spindleSpeedParameter))
                                      : nullptr;
}
} // namespace

int ProgramRules::spindleValue(const Capabilities& caps, const ParameterSchema& schema,
                               std::optional<double> maxRpm, double s)
{
    const ParameterSpec* spec = spindleSpec(caps, schema);
    // The program's S is 0..1 000 000 (ProgramLineChecks), so every value here fits an int.
    if (!maxRpm || *maxRpm <= 0 || !spec || spec->maximum <= 0 || s <= 0)
        return qRound(s);
    const double scaled = FeedLimit::spindleRpm(s, maxRpm) / *maxRpm * double(spec->maximum);
    return std::max(1, qRound(scaled));
}

QString ProgramRules::spindleSpeed(const Capabilities& caps, const ParameterSchema& schema,
                                   std::optional<double> maxRpm, double s,
                                   machine::LimitPolicy limits)
{
    if (maxRpm && s > *maxRpm && limits == machine::LimitPolicy::Refuse)
        return tr("S%1 is above the spindle's maxRpm %2 (the machine file's spindle scale)")
            .arg(s)
            .arg(*maxRpm);
    const ParameterSpec* spec = spindleSpec(caps, schema);
    if (!spec)
        return {};
    return schema.validateScalar(*spec, spindleValue(caps, schema, maxRpm, s));
}

QString ProgramRules::spindleReverse(const Capabilities& caps, const QString& controller,
                                     const machine::MachineSpindle& spindle)
{
    if (caps.spindleReverse || spindle.laser)
        return {};
    return tr("controller \"%1\" cannot reverse its spindle: use M3").arg(controller);
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
