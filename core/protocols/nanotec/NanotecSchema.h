#pragma once
#include "model/ParameterSchema.h"
#include <QByteArray>
#include <optional>

namespace stepdeck::nanotec {

// How a parameter travels on the wire. The schema (ParameterSpec) is what forms and the CLI
// see; ParamDef adds the command that carries it.
struct ParamDef
{
    enum class Read {
        Z,         // "Z<cmd>" (section 3), e.g. "#1Zi\r" -> "001Zi50\r"
        Long,      // ":<keyword>" (1.2)
        Direct,    // the command itself answers with its value ('C', 'I', '$', 'M', 'E')
        LastError, // 'E' gives the slot of the last error, "ZE<slot>" its code (5.15)
    };
    ParameterSpec spec;
    QByteArray cmd; // "i", "l", "CL_motor_pp"
    Read read = Read::Z;
    // Choice: wire value per entry of spec.choices. With fieldMask set the choices are bit
    // patterns inside a shared bitmask (the limit-switch behaviour groups of 'l').
    QList<qint64> choiceValues;
    qint64 fieldMask = 0; // bits of the command's value this parameter owns (0: all)
    qint64 validBits = 0; // masks (5.24-5.30): bits the manual allows; 0: no bit check
    bool record = false;  // stored in records (section 4)

    bool isLong() const { return read == Read::Long; }
    bool isBitField() const { return fieldMask != 0 && spec.type == ParameterType::Choice; }
};

const QList<ParamDef>& parameterTable();
const ParamDef* findParam(const QString& name);
const ParamDef* findRecordField(char cmd); // 'p', 's', ... (section 4)
ParameterSchema parameterSchema();

// Schema value (normalised) -> wire value. For bit fields: the group's bits only.
std::optional<qint64> toWire(const ParamDef& def, const QVariant& value);
// Wire value -> schema value. A choice the drive reports that matches no entry comes back as
// "invalid (N)", so it is visible and fails validation on import.
QVariant fromWire(const ParamDef& def, qint64 wire);
// Checks that go beyond the schema's ranges (mask bits, 5.24-5.30); empty when fine.
QString extraValidation(const ParamDef& def, const QVariant& value);

} // namespace stepdeck::nanotec
