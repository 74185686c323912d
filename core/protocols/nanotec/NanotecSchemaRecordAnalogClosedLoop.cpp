// Sections of the parameter table (NanotecSchemaBuilder.h): records (section 4), analog input
// and joystick, closed loop (8.x) and the read-only values. Motor, limit switches, encoder and
// inputs/outputs are in NanotecSchema.cpp.
#include "NanotecSchemaBuilder.h"

namespace stepdeck::nanotec::schema {

void record(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Record"));
    const int first = int(b.defs.size());
    b.add("positioning-mode", QT_TRANSLATE_NOOP("Parameters", "Positioning mode"), "p", 1, 4, "", 1,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Meaning depends on the motor mode (6.6). Positioning: 1 relative, 2 absolute, "
              "3 internal reference run, 4 external reference run. Speed: 1 speed mode; 2 is not "
              "used there and is ignored."));
    b.add("travel-distance", QT_TRANSLATE_NOOP("Parameters", "Travel distance"), "s", -2147483648LL,
          2147483647LL, QT_TRANSLATE_NOOP("Parameters", "steps"), 400,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Relative: distance (positive, direction from 'direction'); absolute: target "
              "position. Full steps in adaptive mode (6.7)"));
    b.add("min-frequency", QT_TRANSLATE_NOOP("Parameters", "Minimum frequency"), "u", 60, 25000,
          QT_TRANSLATE_NOOP("Parameters", "Hz"), 400,
          QT_TRANSLATE_NOOP("Parameters", "Start speed of a run in steps per second (6.8)"));
    b.add("max-frequency", QT_TRANSLATE_NOOP("Parameters", "Maximum frequency"), "o", 60, 25000,
          QT_TRANSLATE_NOOP("Parameters", "Hz"), 1000,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Top speed reached after the acceleration ramp, in steps per second (6.9)"));
    b.add("max-frequency-2", QT_TRANSLATE_NOOP("Parameters", "Maximum frequency 2"), "n", 60, 25000,
          QT_TRANSLATE_NOOP("Parameters", "Hz"), 1000,
          QT_TRANSLATE_NOOP("Parameters",
                            "Top speed after the trigger in flag positioning mode (6.10)"));
    b.add("ramp", QT_TRANSLATE_NOOP("Parameters", "Ramp"), "b", 1, 65535, "", 2364,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Acceleration and braking ramp: acceleration in Hz/ms = 3000 / sqrt(ramp) - 11.7 "
              "(6.11)"));
    b.choice("direction", QT_TRANSLATE_NOOP("Parameters", "Direction"), "d",
             {{QT_TRANSLATE_NOOP("Parameters", "left"), 0},
              {QT_TRANSLATE_NOOP("Parameters", "right"), 1}},
             "left",
             QT_TRANSLATE_NOOP("Parameters",
                               "Direction of rotation; 'right' counts positions up (6.12)"));
    b.boolean("direction-reversal", QT_TRANSLATE_NOOP("Parameters", "Reverse on repetition"), "t",
              false,
              QT_TRANSLATE_NOOP("Parameters",
                                "Reverse the direction on every repetition of the record (6.13)"));
    b.add("repetitions", QT_TRANSLATE_NOOP("Parameters", "Repetitions"), "W", 0, 254, "", 1,
          QT_TRANSLATE_NOOP("Parameters",
                            "Number of runs of the record; 0 repeats endlessly (6.14)"));
    b.add("record-pause", QT_TRANSLATE_NOOP("Parameters", "Record pause"), "P", 0, 65535,
          QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP("Parameters",
                            "Pause between repetitions or before the next record (6.15)"));
    b.add("next-record", QT_TRANSLATE_NOOP("Parameters", "Next record"), "N", 0, 32, "", 0,
          QT_TRANSLATE_NOOP("Parameters", "Record run after this one; 0: none (6.16)"));
    for (int i = first; i < b.defs.size(); ++i)
        b.defs[i].record = true;
}

void analog(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Analog & joystick"));
    b.add("joystick-dead-zone", QT_TRANSLATE_NOOP("Parameters", "Joystick dead zone"), "=", 0, 100,
          QT_TRANSLATE_NOOP("Parameters", "%"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Range around the middle of the analog input in which the motor stands still in "
              "joystick mode (7.1)"));
    b.add("analog-filter", QT_TRANSLATE_NOOP("Parameters", "Analog filter"), "f", 0, 16,
          QT_TRANSLATE_NOOP("Parameters", "samples"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Samples averaged for the analog input in analog and joystick mode (7.2)"));
    b.add("analog-min-voltage", QT_TRANSLATE_NOOP("Parameters", "Analog range start"), "Q", -100,
          100, QT_TRANSLATE_NOOP("Parameters", "x0.1 V"), -100,
          QT_TRANSLATE_NOOP("Parameters", "Start of the analog input range (7.3)"));
    b.add("analog-max-voltage", QT_TRANSLATE_NOOP("Parameters", "Analog range end"), "R", -100, 100,
          QT_TRANSLATE_NOOP("Parameters", "x0.1 V"), 100,
          QT_TRANSLATE_NOOP("Parameters", "End of the analog input range (7.4)"));
    b.add("analog-dead-zone", QT_TRANSLATE_NOOP("Parameters", "Analog input dead zone"),
          QT_TRANSLATE_NOOP("Parameters", "%"), 0, 100, QT_TRANSLATE_NOOP("Parameters", "%"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Dead zone of the analog input in percent of the range, joystick mode (7.5)"));
}

void closedLoop(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Closed loop"));
    const char* overspeed = QT_TRANSLATE_NOOP(
        "Parameters",
        "If pole pairs or encoder counts do not match the motor, or no calibration run was made "
        "for this motor, the motor can speed up beyond its mechanical limits (manual 8.1).");
    ParamDef& en = b.boolean(
        "cl-enable", QT_TRANSLATE_NOOP("Parameters", "Closed loop enabled"), "CL_enable", false,
        QT_TRANSLATE_NOOP("Parameters",
                          "Activates the control loop; only possible after the special "
                          "reference run (mode 8) since power-on (8.1)"),
        Read::Long);
    en.spec.warning = QString::fromLatin1(overspeed);
    b.add(
        "cl-position-window", QT_TRANSLATE_NOOP("Parameters", "Position window"),
        "CL_position_window", 0, 4294967295LL, QT_TRANSLATE_NOOP("Parameters", "increments"), 0,
        QT_TRANSLATE_NOOP("Parameters", "Tolerance around the target that counts as reached (8.2)"),
        Read::Long);
    b.add("cl-position-window-time", QT_TRANSLATE_NOOP("Parameters", "Position window time"),
          "CL_position_window_time", 0, 65535, QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP("Parameters", "How long the position must stay in the window (8.3)"),
          Read::Long);
    b.add("cl-following-error-window", QT_TRANSLATE_NOOP("Parameters", "Following error window"),
          "CL_following_error_window", 0, 4294967295LL,
          QT_TRANSLATE_NOOP("Parameters", "increments"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Largest allowed following error; beyond it a position error switches the loop off "
              "(8.4)"),
          Read::Long);
    b.add(
        "cl-following-error-timeout", QT_TRANSLATE_NOOP("Parameters", "Following error time"),
        "CL_following_error_timeout", 0, 65535, QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
        QT_TRANSLATE_NOOP("Parameters", "How long the following error may exceed the window (8.5)"),
        Read::Long);
    ParamDef& pp = b.choice(
        "cl-motor-pole-pairs", QT_TRANSLATE_NOOP("Parameters", "Motor pole pairs"), "CL_motor_pp",
        {{"50", 50}, {"100", 100}}, "50",
        QT_TRANSLATE_NOOP("Parameters",
                          "Quarter of the full steps per revolution; changes step-angle as "
                          "well (8.6)"),
        Read::Long);
    // One sentence per warning, so that translators see it whole.
    const QString ppWarning = QString::fromUtf8(QT_TRANSLATE_NOOP(
        "Parameters",
        "If pole pairs or encoder counts do not match the motor, or no calibration run was made "
        "for this motor, the motor can speed up beyond its mechanical limits (manual 8.1). The "
        "firmware must be restarted (power off) after a change."));
    pp.spec.warning = ppWarning;
    ParamDef& inc = b.choice(
        "cl-encoder-increments", QT_TRANSLATE_NOOP("Parameters", "Encoder increments"),
        "CL_rotenc_inc", {{"1600", 1600}, {"2000", 2000}}, "2000",
        QT_TRANSLATE_NOOP("Parameters", "Encoder increments per cl-encoder-revolutions (8.7)"),
        Read::Long);
    inc.spec.warning = ppWarning; // pp may have moved: QList grew
    ParamDef& rev =
        b.add("cl-encoder-revolutions", QT_TRANSLATE_NOOP("Parameters", "Encoder revolutions"),
              "CL_rotenc_rev", 1, 1, "", 1,
              QT_TRANSLATE_NOOP("Parameters",
                                "Shaft revolutions for cl-encoder-increments; always 1 (8.8)"),
              Read::Long);
    rev.spec.warning = QString::fromUtf8(
        QT_TRANSLATE_NOOP("Parameters", "Other values stop the control loop from working. The "
                                        "firmware must be restarted (power off) after a change."));
    struct Gain
    {
        const char* name;
        const char* numerator;
        const char* denominator;
        const char* kw;
    };
    const Gain gains[] = {
        {"cl-kp-v", QT_TRANSLATE_NOOP("Parameters", "Speed loop P numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Speed loop P denominator"), "CL_KP_v"},
        {"cl-ki-v", QT_TRANSLATE_NOOP("Parameters", "Speed loop I numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Speed loop I denominator"), "CL_KI_v"},
        {"cl-kd-v", QT_TRANSLATE_NOOP("Parameters", "Speed loop D numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Speed loop D denominator"), "CL_KD_v"},
        {"cl-kp-s", QT_TRANSLATE_NOOP("Parameters", "Position loop P numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Position loop P denominator"), "CL_KP_s"},
        {"cl-ki-s", QT_TRANSLATE_NOOP("Parameters", "Position loop I numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Position loop I denominator"), "CL_KI_s"},
        {"cl-kd-s", QT_TRANSLATE_NOOP("Parameters", "Position loop D numerator"),
         QT_TRANSLATE_NOOP("Parameters", "Position loop D denominator"), "CL_KD_s"},
    };
    for (const Gain& g : gains) {
        const QByteArray base(g.name), kw(g.kw);
        ParamDef& z =
            b.add("", g.numerator, "", 0, 65535, "", 0,
                  QT_TRANSLATE_NOOP("Parameters", "Numerator of the controller term (8.9-8.20)"),
                  Read::Long);
        z.spec.name = QString::fromLatin1(base + "-numerator");
        z.cmd = kw + "_Z";
        ParamDef& n =
            b.add("", g.denominator, "", 0, 15, QT_TRANSLATE_NOOP("Parameters", "2^n"), 0,
                  QT_TRANSLATE_NOOP("Parameters",
                                    "Denominator of the controller term as a power of two: 0 = 1, "
                                    "1 = 2, 2 = 4, ... (8.9-8.20)"),
                  Read::Long);
        n.spec.name = QString::fromLatin1(base + "-denominator");
        n.cmd = kw + "_N";
    }
}

void readOnly(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Status"));
    b.add("position", QT_TRANSLATE_NOOP("Parameters", "Position"), "C", -2147483648LL, 2147483647LL,
          QT_TRANSLATE_NOOP("Parameters", "steps"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Position in steps of the current step mode, relative to the last reference (5.17)"),
          Read::Direct);
    b.add("encoder-position", QT_TRANSLATE_NOOP("Parameters", "Encoder position"), "I",
          -2147483648LL, 2147483647LL, QT_TRANSLATE_NOOP("Parameters", "steps"), 0,
          QT_TRANSLATE_NOOP("Parameters", "Position according to the encoder (5.16)"),
          Read::Direct);
    b.add("status-word", QT_TRANSLATE_NOOP("Parameters", "Status"), "$", 0, 255,
          QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Bit 0 ready, 1 zero position reached, 2 position error, 3 input 1 set while ready, "
              "4-6 mode (5.21)"),
          Read::Direct);
    b.add("bus-address", QT_TRANSLATE_NOOP("Parameters", "Bus address"), "M", 1, 254, "", 1,
          QT_TRANSLATE_NOOP("Parameters", "The address the drive answers at (5.20)"), Read::Direct);
    b.choice("last-error", QT_TRANSLATE_NOOP("Parameters", "Last error"), "E",
             {{QT_TRANSLATE_NOOP("Parameters", "none"), 0},
              {QT_TRANSLATE_NOOP("Parameters", "low-voltage"), 0x01},
              {QT_TRANSLATE_NOOP("Parameters", "over-temperature"), 0x02},
              {QT_TRANSLATE_NOOP("Parameters", "driver"), 0x04},
              {QT_TRANSLATE_NOOP("Parameters", "eeprom"), 0x08},
              {QT_TRANSLATE_NOOP("Parameters", "position"), 0x10},
              {QT_TRANSLATE_NOOP("Parameters", "internal"), 0x20}},
             "none",
             QT_TRANSLATE_NOOP("Parameters", "Most recent entry of the error memory (5.15)"),
             Read::LastError);
}
} // namespace stepdeck::nanotec::schema
