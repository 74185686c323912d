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
        s.label = QString::fromUtf8(label);
        s.group = QString::fromUtf8(group);
        s.unit = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "steps/s"));
        s.type = ParameterType::Integer;
        s.minimum = 0;
        s.maximum = 0xFFFF; // 16-bit words without sign
        s.perAxis = true;
        s.defaultValue = def;
        s.description = QString::fromUtf8(desc);
        return s;
    };
    QList<ParameterSpec> specs;
    specs << speed(
        "start-speed", QT_TRANSLATE_NOOP("Parameters", "Start speed"),
        QT_TRANSLATE_NOOP("Parameters", "Speeds"),
        QT_TRANSLATE_NOOP("Parameters", "Step rate at the start of a ramp (SetStartSpeed, <ESC>S)"),
        100);
    specs << speed(
        "max-speed", QT_TRANSLATE_NOOP("Parameters", "Max speed"),
        QT_TRANSLATE_NOOP("Parameters", "Speeds"),
        QT_TRANSLATE_NOOP(
            "Parameters",
            "Plateau step rate of positioning and reference moves (SetMaxSpeed, <ESC>M)"),
        5000);
    specs << speed(
        "feed-speed", QT_TRANSLATE_NOOP("Parameters", "Feed speed"),
        QT_TRANSLATE_NOOP("Parameters", "Speeds"),
        QT_TRANSLATE_NOOP("Parameters",
                          "Step rate in feed mode; must be below the start speed, feed has no ramp "
                          "(SetFeedSpeed, <FS>)"),
        50);
    ParameterSpec accel =
        speed("acceleration", QT_TRANSLATE_NOOP("Parameters", "Acceleration"),
              QT_TRANSLATE_NOOP("Parameters", "Acceleration"),
              QT_TRANSLATE_NOOP("Parameters",
                                "Ramp steepness of positioning moves; sensible values are 500 to "
                                "2000 (SetAcceleration, <ESC>A)"),
              1000);
    // The manual gives no unit (SetAcceleration: "Je größer die Werte desto steiler ist die
    // Rampe"): the column says so instead of guessing one.
    accel.unit = QString();
    accel.unitNote = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "(no unit)"));
    accel.unitNoteDetail = QString::fromUtf8(
        QT_TRANSLATE_NOOP("Parameters", "The E-LAB manual gives no unit for the acceleration, "
                                        "only its scale: the larger the value, the steeper the "
                                        "ramp (SetAcceleration)."));
    specs << accel;

    auto polarity = [](const char* name, const char* label, const char* desc) {
        ParameterSpec s;
        s.name = QString::fromLatin1(name);
        s.label = QString::fromUtf8(label);
        s.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Switch polarity"));
        s.type = ParameterType::Choice;
        s.choices = {QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "high")),
                     QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "low"))};
        s.perAxis = true;
        s.defaultValue = QStringLiteral("low");
        s.description = QString::fromUtf8(desc);
        return s;
    };
    specs << polarity(
        "limit-polarity", QT_TRANSLATE_NOOP("Parameters", "Limit switch polarity"),
        QT_TRANSLATE_NOOP("Parameters",
                          "Active level of the limit switches (SetSwitchPolarity, <SO>)"));
    specs << polarity(
        "reference-polarity", QT_TRANSLATE_NOOP("Parameters", "Reference switch polarity"),
        QT_TRANSLATE_NOOP("Parameters",
                          "Active level of the reference switches (SetSwitchPolarity, <DLE>)"));

    ParameterSpec power;
    power.name = QStringLiteral("drive-power");
    power.label = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Drive power"));
    power.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Power & spindle"));
    power.unit = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "%"));
    power.minimum = 0;
    power.maximum = 100;
    power.defaultValue = 100;
    power.description = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "Motor current for all axes; the board maps it to off (<25), 33 % (<50), 66 % (<75), "
        "100 % (SetDrivePower, <STX>)"));
    specs << power;

    ParameterSpec rpm;
    rpm.name = QStringLiteral("spindle-rpm");
    rpm.label = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Spindle speed"));
    rpm.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Power & spindle"));
    rpm.unit = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "rpm"));
    rpm.minimum = 0;
    rpm.maximum = 1000;
    rpm.defaultValue = 0;
    rpm.description = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "0 switches the spindle relay off, anything above switches it on (SetSpindleRPM, <SOH>)"));
    specs << rpm;

    ParameterSpec cool;
    cool.name = QStringLiteral("coolant");
    cool.label = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Coolant"));
    cool.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Power & spindle"));
    cool.type = ParameterType::Boolean;
    cool.defaultValue = false;
    cool.description = QString::fromUtf8(
        QT_TRANSLATE_NOOP("Parameters", "Coolant pump relay RS2 (SetCoolOnOff, <SI>)"));
    specs << cool;
    return ParameterSchema(specs);
}

} // namespace stepdeck::elab
