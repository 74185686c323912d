// Record, analog/joystick, closed-loop and read-only parts of the parameter table.
#include "NanotecSchemaBuilder.h"

namespace stepdeck::nanotec::schema {

void record(Builder& b)
{
    b.group = QStringLiteral("Record");
    const int first = int(b.defs.size());
    b.add("positioning-mode", "Positioning mode", "p", 1, 4, "", 1,
          "Meaning depends on the motor mode (6.6). Positioning: 1 relative, 2 absolute, "
          "3 internal reference run, 4 external reference run. Speed: 1 speed mode; 2 is not "
          "used there and is ignored.");
    b.add("travel-distance", "Travel distance", "s", -2147483648LL, 2147483647LL, "steps", 400,
          "Relative: distance (positive, direction from 'direction'); absolute: target "
          "position. Full steps in adaptive mode (6.7)");
    b.add("min-frequency", "Minimum frequency", "u", 60, 25000, "Hz", 400,
          "Start speed of a run in steps per second (6.8)");
    b.add("max-frequency", "Maximum frequency", "o", 60, 25000, "Hz", 1000,
          "Top speed reached after the acceleration ramp, in steps per second (6.9)");
    b.add("max-frequency-2", "Maximum frequency 2", "n", 60, 25000, "Hz", 1000,
          "Top speed after the trigger in flag positioning mode (6.10)");
    b.add("ramp", "Ramp", "b", 1, 65535, "", 2364,
          "Acceleration and braking ramp: acceleration in Hz/ms = 3000 / sqrt(ramp) - 11.7 "
          "(6.11)");
    b.choice("direction", "Direction", "d", {{"left", 0}, {"right", 1}}, "left",
             "Direction of rotation; 'right' counts positions up (6.12)");
    b.boolean("direction-reversal", "Reverse on repetition", "t", false,
              "Reverse the direction on every repetition of the record (6.13)");
    b.add("repetitions", "Repetitions", "W", 0, 254, "", 1,
          "Number of runs of the record; 0 repeats endlessly (6.14)");
    b.add("record-pause", "Record pause", "P", 0, 65535, "ms", 0,
          "Pause between repetitions or before the next record (6.15)");
    b.add("next-record", "Next record", "N", 0, 32, "", 0,
          "Record run after this one; 0: none (6.16)");
    for (int i = first; i < b.defs.size(); ++i)
        b.defs[i].record = true;
}

void analog(Builder& b)
{
    b.group = QStringLiteral("Analog & joystick");
    b.add("joystick-dead-zone", "Joystick dead zone", "=", 0, 100, "%", 0,
          "Range around the middle of the analog input in which the motor stands still in "
          "joystick mode (7.1)");
    b.add("analog-filter", "Analog filter", "f", 0, 16, "samples", 0,
          "Samples averaged for the analog input in analog and joystick mode (7.2)");
    b.add("analog-min-voltage", "Analog range start", "Q", -100, 100, "x0.1 V", -100,
          "Start of the analog input range (7.3)");
    b.add("analog-max-voltage", "Analog range end", "R", -100, 100, "x0.1 V", 100,
          "End of the analog input range (7.4)");
    b.add("analog-dead-zone", "Analog input dead zone", "%", 0, 100, "%", 0,
          "Dead zone of the analog input in percent of the range, joystick mode (7.5)");
}

void closedLoop(Builder& b)
{
    b.group = QStringLiteral("Closed loop");
    const char* overspeed =
        "If pole pairs or encoder counts do not match the motor, or no calibration run was made "
        "for this motor, the motor can speed up beyond its mechanical limits (manual 8.1).";
    ParamDef& en = b.boolean("cl-enable", "Closed loop enabled", "CL_enable", false,
                             "Activates the control loop; only possible after the special "
                             "reference run (mode 8) since power-on (8.1)",
                             Read::Long);
    en.spec.warning = QString::fromLatin1(overspeed);
    b.add("cl-position-window", "Position window", "CL_position_window", 0, 4294967295LL,
          "increments", 0, "Tolerance around the target that counts as reached (8.2)", Read::Long);
    b.add("cl-position-window-time", "Position window time", "CL_position_window_time", 0, 65535,
          "ms", 0, "How long the position must stay in the window (8.3)", Read::Long);
    b.add("cl-following-error-window", "Following error window", "CL_following_error_window", 0,
          4294967295LL, "increments", 0,
          "Largest allowed following error; beyond it a position error switches the loop off "
          "(8.4)",
          Read::Long);
    b.add("cl-following-error-timeout", "Following error time", "CL_following_error_timeout", 0,
          65535, "ms", 0, "How long the following error may exceed the window (8.5)", Read::Long);
    const QString restart = QStringLiteral(" The firmware must be restarted (power off) after a "
                                           "change.");
    ParamDef& pp = b.choice("cl-motor-pole-pairs", "Motor pole pairs", "CL_motor_pp",
                            {{"50", 50}, {"100", 100}}, "50",
                            "Quarter of the full steps per revolution; changes step-angle as "
                            "well (8.6)",
                            Read::Long);
    const QString ppWarning = QString::fromLatin1(overspeed) + restart;
    pp.spec.warning = ppWarning;
    ParamDef& inc = b.choice("cl-encoder-increments", "Encoder increments", "CL_rotenc_inc",
                             {{"1600", 1600}, {"2000", 2000}}, "2000",
                             "Encoder increments per cl-encoder-revolutions (8.7)", Read::Long);
    inc.spec.warning = ppWarning; // pp may have moved: QList grew
    ParamDef& rev =
        b.add("cl-encoder-revolutions", "Encoder revolutions", "CL_rotenc_rev", 1, 1, "", 1,
              "Shaft revolutions for cl-encoder-increments; always 1 (8.8)", Read::Long);
    rev.spec.warning = QStringLiteral("Other values stop the control loop from working.") + restart;
    struct Gain
    {
        const char* name;
        const char* label;
        const char* kw;
    };
    const Gain gains[] = {
        {"cl-kp-v", "Speed loop P", "CL_KP_v"},    {"cl-ki-v", "Speed loop I", "CL_KI_v"},
        {"cl-kd-v", "Speed loop D", "CL_KD_v"},    {"cl-kp-s", "Position loop P", "CL_KP_s"},
        {"cl-ki-s", "Position loop I", "CL_KI_s"}, {"cl-kd-s", "Position loop D", "CL_KD_s"},
    };
    for (const Gain& g : gains) {
        const QByteArray base(g.name), label(g.label), kw(g.kw);
        ParamDef& z = b.add("", "", "", 0, 65535, "", 0,
                            "Numerator of the controller term (8.9-8.20)", Read::Long);
        z.spec.name = QString::fromLatin1(base + "-numerator");
        z.spec.label = QString::fromLatin1(label + " numerator");
        z.cmd = kw + "_Z";
        ParamDef& n = b.add("", "", "", 0, 15, "2^n", 0,
                            "Denominator of the controller term as a power of two: 0 = 1, "
                            "1 = 2, 2 = 4, ... (8.9-8.20)",
                            Read::Long);
        n.spec.name = QString::fromLatin1(base + "-denominator");
        n.spec.label = QString::fromLatin1(label + " denominator");
        n.cmd = kw + "_N";
    }
}

void readOnly(Builder& b)
{
    b.group = QStringLiteral("Status");
    b.add("position", "Position", "C", -2147483648LL, 2147483647LL, "steps", 0,
          "Position in steps of the current step mode, relative to the last reference (5.17)",
          Read::Direct);
    b.add("encoder-position", "Encoder position", "I", -2147483648LL, 2147483647LL, "steps", 0,
          "Position according to the encoder (5.16)", Read::Direct);
    b.add("status-word", "Status", "$", 0, 255, "bitmask", 0,
          "Bit 0 ready, 1 zero position reached, 2 position error, 3 input 1 set while ready, "
          "4-6 mode (5.21)",
          Read::Direct);
    b.add("bus-address", "Bus address", "M", 1, 254, "", 1,
          "The address the drive answers at (5.20)", Read::Direct);
    b.choice("last-error", "Last error", "E",
             {{"none", 0},
              {"low-voltage", 0x01},
              {"over-temperature", 0x02},
              {"driver", 0x04},
              {"eeprom", 0x08},
              {"position", 0x10},
              {"internal", 0x20}},
             "none", "Most recent entry of the error memory (5.15)", Read::LastError);
}
} // namespace stepdeck::nanotec::schema
