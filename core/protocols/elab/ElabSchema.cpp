// The E-LAB parameter schema (pure data, no controller or simulator): setup pages, CLI
// set/export/import and the parameter-file fuzzer use it.
#include "ElabModel.h"

namespace stepdeck::elab {

ParameterSchema parameterSchema()
{
    // No E-LAB command reads a parameter back: everything is write-only (readable = false).
    auto speed = [](const char* name, const char* label, const char* group, const char* desc,
                    qint64 def) {
        ParameterSpec s;
        s.name = QString::fromLatin1(name);
        s.label = QString::fromLatin1(label);
        s.group = QString::fromLatin1(group);
        s.unit = QStringLiteral("steps/s");
        s.type = ParameterType::Integer;
        s.minimum = 0;
        s.maximum = 0xFFFF; // 16-bit words without sign
        s.perAxis = true;
        s.defaultValue = def;
        s.description = QString::fromLatin1(desc);
        return s;
    };
    QList<ParameterSpec> specs;
    specs << speed("start-speed", "Start speed", "Speeds",
                   "Step rate at the start of a ramp (SetStartSpeed, <ESC>S)", 100);
    specs << speed("max-speed", "Max speed", "Speeds",
                   "Plateau step rate of positioning and reference moves (SetMaxSpeed, <ESC>M)",
                   5000);
    specs << speed("feed-speed", "Feed speed", "Speeds",
                   "Step rate in feed mode; must be below the start speed, feed has no ramp "
                   "(SetFeedSpeed, <FS>)",
                   50);
    ParameterSpec accel = speed("acceleration", "Acceleration", "Acceleration",
                                "Ramp steepness of positioning moves; sensible values are 500 to "
                                "2000 (SetAcceleration, <ESC>A)",
                                1000);
    accel.unit = QString();
    specs << accel;

    auto polarity = [](const char* name, const char* label, const char* desc) {
        ParameterSpec s;
        s.name = QString::fromLatin1(name);
        s.label = QString::fromLatin1(label);
        s.group = QStringLiteral("Switch polarity");
        s.type = ParameterType::Choice;
        s.choices = {QStringLiteral("high"), QStringLiteral("low")};
        s.perAxis = true;
        s.defaultValue = QStringLiteral("low");
        s.description = QString::fromLatin1(desc);
        return s;
    };
    specs << polarity("limit-polarity", "Limit switch polarity",
                      "Active level of the limit switches (SetSwitchPolarity, <SO>)");
    specs << polarity("reference-polarity", "Reference switch polarity",
                      "Active level of the reference switches (SetSwitchPolarity, <DLE>)");

    ParameterSpec power;
    power.name = QStringLiteral("drive-power");
    power.label = QStringLiteral("Drive power");
    power.group = QStringLiteral("Power & spindle");
    power.unit = QStringLiteral("%");
    power.minimum = 0;
    power.maximum = 100;
    power.defaultValue = 100;
    power.description = QStringLiteral(
        "Motor current for all axes; the board maps it to off (<25), 33 % (<50), 66 % (<75), "
        "100 % (SetDrivePower, <STX>)");
    specs << power;

    ParameterSpec rpm;
    rpm.name = QStringLiteral("spindle-rpm");
    rpm.label = QStringLiteral("Spindle speed");
    rpm.group = QStringLiteral("Power & spindle");
    rpm.unit = QStringLiteral("rpm");
    rpm.minimum = 0;
    rpm.maximum = 1000;
    rpm.defaultValue = 0;
    rpm.description = QStringLiteral(
        "0 switches the spindle relay off, anything above switches it on (SetSpindleRPM, <SOH>)");
    specs << rpm;

    ParameterSpec cool;
    cool.name = QStringLiteral("coolant");
    cool.label = QStringLiteral("Coolant");
    cool.group = QStringLiteral("Power & spindle");
    cool.type = ParameterType::Boolean;
    cool.defaultValue = false;
    cool.description = QStringLiteral("Coolant pump relay RS2 (SetCoolOnOff, <SI>)");
    specs << cool;
    return ParameterSchema(specs);
}

} // namespace stepdeck::elab
