// The SMC-IC4 schema's labels, groups, units, choices, descriptions and warnings are data
// (English); the UI shows them through QCoreApplication::translate("Parameters", ...). Listed
// here so lupdate finds them (keep in step with EmisModel.cpp; tst_emismodel checks that).
#include <QtGlobal>

namespace stepdeck::emis {

namespace {
[[maybe_unused]] const char* const kParameterStrings[] = {
    QT_TRANSLATE_NOOP("Parameters", "Speeds"),
    QT_TRANSLATE_NOOP("Parameters", "Start speed"),
    QT_TRANSLATE_NOOP("Parameters", "steps/s"),
    QT_TRANSLATE_NOOP("Parameters", "Speed at which every move starts and ends its ramp (#S, 9.4)"),
    QT_TRANSLATE_NOOP("Parameters", "Work speed"),
    QT_TRANSLATE_NOOP("Parameters", "Speed of vector moves after the ramp (#E1, 9.5)"),
    QT_TRANSLATE_NOOP("Parameters", "Ramp"),
    QT_TRANSLATE_NOOP("Parameters", "ms"),
    QT_TRANSLATE_NOOP("Parameters",
                      "Time from start speed to work speed and back, all motors (#R, 9.6)"),
    QT_TRANSLATE_NOOP("Parameters", "Referencing"),
    QT_TRANSLATE_NOOP("Parameters", "Reference speed"),
    QT_TRANSLATE_NOOP("Parameters", "Speed of reference runs, one value for all motors (#E9, 9.5)"),
    QT_TRANSLATE_NOOP("Parameters", "Offset after referencing"),
    QT_TRANSLATE_NOOP("Parameters", "steps"),
    QT_TRANSLATE_NOOP("Parameters", "Steps the motor moves out of its switch after a reference run "
                                    "(#O, 9.10); not a system parameter"),
    QT_TRANSLATE_NOOP("Parameters", "Reference switch type"),
    QT_TRANSLATE_NOOP("Parameters", "NO: normally open (Schließer, the default), NC: normally "
                                    "closed (Öffner); inputs 1-4 (##REFSW, 9.14, 5.2.1)"),
    QT_TRANSLATE_NOOP("Parameters", "NO"),
    QT_TRANSLATE_NOOP("Parameters", "NC"),
    QT_TRANSLATE_NOOP(
        "Parameters",
        "The type must match the wired switches, or reference runs end in the wrong place. It is "
        "stored in the board's system parameters and kept after power-off."),
    QT_TRANSLATE_NOOP("Parameters", "Drive"),
    QT_TRANSLATE_NOOP("Parameters", "Step resolution"),
    QT_TRANSLATE_NOOP("Parameters", "microsteps"),
    QT_TRANSLATE_NOOP("Parameters", "Microsteps per full step (D, 9.7)"),
    QT_TRANSLATE_NOOP("Parameters", "Changes the length of a step: every position, distance and "
                                    "speed in steps changes its meaning."),
    QT_TRANSLATE_NOOP("Parameters", "Run current"),
    QT_TRANSLATE_NOOP("Parameters", "%"),
    QT_TRANSLATE_NOOP("Parameters",
                      "Motor current while moving, % of the driver's rating (c, 9.8)"),
    QT_TRANSLATE_NOOP("Parameters",
                      "A current above the motor's rating overheats motor and driver stage."),
    QT_TRANSLATE_NOOP("Parameters", "Idle current"),
    QT_TRANSLATE_NOOP("Parameters", "Motor current at standstill, % of the driver's rating (c, "
                                    "9.8); 0 leaves the motor without holding torque"),
    QT_TRANSLATE_NOOP("Parameters", "Interpolation"),
    QT_TRANSLATE_NOOP("Parameters", "On: the axes of a vector move arrive together; off: each axis "
                                    "moves at its own speed (IP, 9.12)"),
    QT_TRANSLATE_NOOP("Parameters", "1"),
    QT_TRANSLATE_NOOP("Parameters", "2"),
    QT_TRANSLATE_NOOP("Parameters", "4"),
    QT_TRANSLATE_NOOP("Parameters", "8"),
    QT_TRANSLATE_NOOP("Parameters", "16"),
    QT_TRANSLATE_NOOP("Parameters", "32"),
    QT_TRANSLATE_NOOP("Parameters", "64"),
    QT_TRANSLATE_NOOP("Parameters", "128"),
    QT_TRANSLATE_NOOP("Parameters", "256"),
};
} // namespace

} // namespace stepdeck::emis
