#pragma once
// The real parameter schemas for the parameter-file and NAME=V targets, with the axes each
// model's machines have.
#include "protocols/elab/ElabModel.h"
#include "protocols/nanotec/NanotecSchema.h"

namespace fuzz {

struct ModelSchema
{
    QString id;
    stepdeck::ParameterSchema schema;
    QList<stepdeck::Axis> axes;
};

inline const QList<ModelSchema>& schemas()
{
    using stepdeck::Axis;
    static const QList<ModelSchema> all{
        {QStringLiteral("elab"), stepdeck::elab::parameterSchema(), {Axis::X, Axis::Y, Axis::Z}},
        {QStringLiteral("nanotec"), stepdeck::nanotec::parameterSchema(), {Axis::X}},
        {QStringLiteral("nanotec"),
         stepdeck::nanotec::parameterSchema(),
         {Axis::X, Axis::Y, Axis::Z, Axis::U}},
    };
    return all;
}

// A value is what the schema promises after parsing: the canonical type, within range.
inline bool canonical(const stepdeck::ParameterSpec& spec, const QVariant& v)
{
    using stepdeck::ParameterType;
    switch (spec.type) {
    case ParameterType::Integer:
        return v.typeId() == QMetaType::LongLong && v.toLongLong() >= spec.minimum &&
               v.toLongLong() <= spec.maximum;
    case ParameterType::Boolean:
        return v.typeId() == QMetaType::Bool;
    case ParameterType::Choice:
        return v.typeId() == QMetaType::QString && spec.choices.contains(v.toString());
    }
    return false;
}

} // namespace fuzz
