// What a program may hold that StepDeck does not run (issue 50: "everything else stays refused
// with a reason that says what it is and what to do instead"): the G and M words of LinuxCNC,
// Fanuc-style posts and 3D printers' slicers that reach StepDeck, each named by what it does.
#include "ProgramLine.h"
#include "ProgramLineChecks.h"

namespace stepdeck::program {

namespace {

QString unsupportedG(int tenths)
{
    switch (tenths) {
    case 50:
    case 51:
    case 52:
    case 53:
        return ProgramLine::tr("%1 (a spline or NURBS curve) is not supported: let the CAM post "
                               "write lines and arcs (G1, G2, G3)");
    case 70:
    case 80:
        return ProgramLine::tr("%1 (a lathe's diameter or radius mode) is not supported: "
                               "StepDeck drives mills, routers, lasers and plotters");
    case 120:
    case 130:
        return ProgramLine::tr("%1 (a circular pocket of some controllers) is not supported: let "
                               "the CAM post write the pocket's arcs (G2, G3)");
    case 160:
        return ProgramLine::tr("%1 (Fanuc's polar coordinates) is not supported: write "
                               "LinuxCNC's @ (the distance) and ^ (the angle)");
    case 281:
    case 300:
    case 301:
        return ProgramLine::tr("%1 (a stored position) is not supported: StepDeck's G28 "
                               "references the axes; go to a machine position with G53 G0");
    case 330:
    case 331:
    case 760:
        return ProgramLine::tr("%1 (threading with the spindle) is not supported: no controller "
                               "of StepDeck's reads its spindle's revolutions");
    case 382:
    case 383:
    case 384:
    case 385:
        return ProgramLine::tr("%1 (a probing move) is not supported: no controller of "
                               "StepDeck's has a probe input; touch off by hand (the DRO's "
                               "Zero) or with G10 L20");
    case 431:
    case 432:
        return ProgramLine::tr("%1 (a tool length written in the program) is not supported: G43 "
                               "H takes the tool table's length, or touch off Z (the machine "
                               "file's \"toolLength\": \"touchOff\")");
    case 520:
        return ProgramLine::tr("%1 (a local offset) is not supported: use G92 or a coordinate "
                               "system (G10 L2, G54 to G59)");
    case 680:
        return ProgramLine::tr("%1 (a rotated coordinate system) is not supported: let the CAM "
                               "post rotate the path");
    case 700:
    case 710:
    case 720:
        return ProgramLine::tr("%1 (a lathe cycle in LinuxCNC, inch or millimetre mode in old "
                               "Fanuc programs) is not supported: write G20 (inch) or G21 (mm) "
                               "for the units");
    case 740:
    case 840:
    case 841:
        return ProgramLine::tr("%1 (a tapping cycle) is not supported: no controller of "
                               "StepDeck's turns its spindle with the feed; G81, G82, G83 and "
                               "G73 are");
    case 850:
    case 860:
    case 870:
    case 880:
    case 890:
        return ProgramLine::tr("%1 (a boring cycle) is not supported: write the holes with G81, "
                               "or G82 for a dwell at the bottom");
    case 960:
        return ProgramLine::tr("%1 (constant surface speed, a lathe's) is not supported: S is "
                               "the spindle's rpm (G97)");
    default:
        return {};
    }
}

// 3D printers' M words, which slicers write: temperatures, fans, the extruder, the motors.
bool printerM(int code)
{
    switch (code) {
    case 82:
    case 83:
    case 84:
    case 104:
    case 105:
    case 106:
    case 107:
    case 109:
    case 117:
    case 140:
    case 190:
    case 220:
    case 221:
        return true;
    default:
        return false;
    }
}

QString unsupportedM(int code)
{
    if (printerM(code))
        return ProgramLine::tr("%1 is a 3D printer's word (temperatures, fans, the extruder): "
                               "not one of machine control; leave it out, or slice for a "
                               "printer");
    if (code == 19)
        return ProgramLine::tr("%1 (orienting the spindle) is not supported: no controller of "
                               "StepDeck's can");
    if (code >= 48 && code <= 53)
        return ProgramLine::tr("%1 (switching the overrides) is not supported: the feed "
                               "override is always the operator's");
    if (code == 60)
        return ProgramLine::tr("%1 (a pallet change) is not supported: write M0 to hold for "
                               "the operator");
    if (code == 61)
        return ProgramLine::tr("%1 (the loaded tool set without a change) is not supported: "
                               "write T<n> M6");
    if (code == 62 || code == 63)
        return ProgramLine::tr("%1 (an output switched with the next move) is not supported: "
                               "M64 and M65 switch it at once");
    if (code == 67 || code == 68)
        return ProgramLine::tr("%1 (an analog output) is not supported: StepDeck's controllers "
                               "have digital outputs (M64, M65)");
    if (code >= 70 && code <= 73)
        return ProgramLine::tr("%1 (saving or restoring the modal state) is not supported: set "
                               "the modes again where they change");
    if (code >= 100 && code <= 199)
        return ProgramLine::tr("%1 (a user-defined M code, a program of a LinuxCNC "
                               "configuration) is not supported");
    return {};
}

} // namespace

QString unsupportedWord(const ProgramWord& word, int tenths)
{
    const bool g = word.letter == QLatin1Char('G');
    const QString why = g                  ? unsupportedG(tenths)
                        : tenths % 10 == 0 ? unsupportedM(tenths / 10)
                                           : QString();
    return why.isEmpty() ? ProgramLine::tr("%1 is not supported").arg(word.valueText())
                         : why.arg(word.valueText());
}

} // namespace stepdeck::program
