#pragma once
// Internal to the schema table (NanotecSchema.cpp, NanotecSchemaRecordAnalogClosedLoop.cpp).
// Labels, groups, units, words of choices, descriptions and warnings are written inside
// QT_TRANSLATE_NOOP("Parameters", ...) where the table names them, so lupdate files them under the
// context ParameterSchema::displayText() translates them with. Numeric choices ("16") and parameter
// names stay unmarked: they are not translated.
#include "NanotecSchema.h"

namespace stepdeck::nanotec::schema {

using Read = ParamDef::Read;

struct Builder
{
    QList<ParamDef> defs;
    QString group;

    ParamDef& add(const char* name, const char* label, const char* cmd, qint64 min, qint64 max,
                  const char* unit, qint64 def, const char* desc, Read read = Read::Z)
    {
        ParamDef d;
        d.spec.name = QString::fromLatin1(name);
        d.spec.label = QString::fromUtf8(label);
        d.spec.group = group;
        d.spec.unit = QString::fromUtf8(unit);
        d.spec.type = ParameterType::Integer;
        d.spec.minimum = min;
        d.spec.maximum = max;
        d.spec.perAxis = true;
        d.spec.readable = true;
        d.spec.writable = read == Read::Z || read == Read::Long;
        d.spec.defaultValue = def;
        d.spec.description = QString::fromUtf8(desc);
        d.cmd = cmd;
        d.read = read;
        defs << d;
        return defs.last();
    }
    ParamDef& choice(const char* name, const char* label, const char* cmd,
                     QList<QPair<const char*, qint64>> entries, const char* def, const char* desc,
                     Read read = Read::Z)
    {
        ParamDef& d = add(name, label, cmd, 0, 0, "", 0, desc, read);
        d.spec.type = ParameterType::Choice;
        for (const auto& e : entries) {
            d.spec.choices << QString::fromUtf8(e.first);
            d.choiceValues << e.second;
        }
        d.spec.defaultValue = QString::fromUtf8(def);
        return d;
    }
    ParamDef& boolean(const char* name, const char* label, const char* cmd, bool def,
                      const char* desc, Read read = Read::Z)
    {
        ParamDef& d = add(name, label, cmd, 0, 1, "", 0, desc, read);
        d.spec.type = ParameterType::Boolean;
        d.spec.defaultValue = def;
        return d;
    }
};

// Sections of the table, in the order forms show them.
void motor(Builder& b);
void limitSwitches(Builder& b);
void encoder(Builder& b);
void inputsOutputs(Builder& b);
void record(Builder& b);
void analog(Builder& b);
void closedLoop(Builder& b);
void readOnly(Builder& b);

} // namespace stepdeck::nanotec::schema
