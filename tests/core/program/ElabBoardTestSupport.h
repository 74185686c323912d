#pragma once
// An E-LAB board in its own steps with what the host knows it holds: the facts the rules
// tests (tst_programrules, tst_moverates) judge a feed's rate writes against.
#include "machine/MachineDescription.h"
#include "program/ProgramCheck.h"
#include "protocols/Registry.h"

namespace stepdeck::program::elabboard {

// MachineDescription::singleController (X, Y, Z in steps), with its model's rules, and
// `known` the values the host knows it holds.
inline MachineFacts elabFacts(const ParameterSet& known)
{
    const ModelInfo* info = findModel(QStringLiteral("elab"));
    MachineFacts f;
    f.description = machine::MachineDescription::singleController(*info, QStringLiteral("sim"));
    f.capabilities.insert("elab", info->capabilities);
    f.schemas.insert("elab", info->schema);
    f.models.insert("elab", info);
    f.knownParameters.insert("elab", known);
    return f;
}

inline ParameterValue perAxis(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return v;
}

// "start=100,100,100 feed=50,50,50": the known parameter values.
inline ParameterSet known(const QString& text)
{
    ParameterSet out;
    for (const QString& pair : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QStringList kv = pair.split(QLatin1Char('='));
        const QStringList v = kv.at(1).split(QLatin1Char(','));
        const QString name = kv.at(0) == QLatin1String("start") ? QStringLiteral("start-speed")
                                                                : QStringLiteral("feed-speed");
        out.insert(name, perAxis(v.at(0).toLongLong(), v.at(1).toLongLong(), v.at(2).toLongLong()));
    }
    return out;
}

} // namespace stepdeck::program::elabboard
