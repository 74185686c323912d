// The whole SMCI33/SMCI47-S command reference as typed parameters. Every parameter belongs to
// one drive, and each drive is one axis, so all of them are per axis.
#include "NanotecSchema.h"

namespace stepdeck::nanotec {

namespace {
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
        d.spec.label = QString::fromLatin1(label);
        d.spec.group = group;
        d.spec.unit = QString::fromLatin1(unit);
        d.spec.type = ParameterType::Integer;
        d.spec.minimum = min;
        d.spec.maximum = max;
        d.spec.perAxis = true;
        d.spec.readable = true;
        d.spec.writable = read == Read::Z || read == Read::Long;
        d.spec.defaultValue = def;
        d.spec.description = QString::fromLatin1(desc);
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
            d.spec.choices << QString::fromLatin1(e.first);
            d.choiceValues << e.second;
        }
        d.spec.defaultValue = QString::fromLatin1(def);
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

const QList<QPair<const char*, qint64>> kSwitchNormal{
    {"free-forward", 0}, {"free-backward", 0}, {"stop", 0}, {"ignore", 0}};

void motor(Builder& b)
{
    b.group = QStringLiteral("Motor");
    b.add("phase-current", "Phase current", "i", 0, 150, "%", 50,
          "Motor current relative to the drive's full scale; values above 100 should be "
          "avoided (5.1)");
    b.add("idle-current", "Idle current", "r", 0, 150, "%", 25,
          "Current at standstill, relative to full scale (not to the phase current); values "
          "above 100 should be avoided (5.2)");
    b.choice("step-mode", "Step mode", "g",
             {{"1", 1},
              {"2", 2},
              {"4", 4},
              {"5", 5},
              {"8", 8},
              {"10", 10},
              {"16", 16},
              {"32", 32},
              {"64", 64},
              {"adaptive", 255}},
             "2", "Microsteps per full step; 'adaptive' selects the adaptive step mode (5.3)");
    b.choice("step-angle", "Step angle", "a", {{"0.9", 9}, {"1.8", 18}}, "1.8",
             "Full-step angle of the motor in degrees, needed to convert encoder positions; "
             "changes cl-motor-pole-pairs as well (5.8, 8.6)")
        .spec.unit = QStringLiteral("deg");
    b.choice("motor-mode", "Motor mode", "!",
             {{"positioning", 1},
              {"speed", 2},
              {"flag-positioning", 3},
              {"clock-direction", 4},
              {"analog", 5},
              {"joystick", 6}},
             "positioning",
             "Operating mode (5.5). Moves, jog and reference runs switch the mode themselves.");
    ParamDef& addr = b.add("motor-address", "Motor address", "m", 1, 254, "", 1,
                           "RS485 bus address of the drive (5.4)");
    addr.spec.warning = QStringLiteral(
        "Communication continues at the new address. It must not be used by another drive on "
        "the bus, or no communication is possible any more (manual 5.4).");
    b.add("backlash", "Backlash", "z", 0, 9999, "steps", 0,
          "Steps made on a direction change before the position counts, to take up gear play "
          "(5.33)");
    b.boolean("auto-status", "Send status after moves", "J", true,
              "The drive sends its status ('j') by itself at the end of every move; the adapter "
              "switches this on when it connects (5.31)");
    b.choice("ramp-mode", "Ramp shape", "CL_ramp_mode", {{"trapezoid", 0}, {"sinus", 1}},
             "trapezoid", "Ramp of the positioning mode (5.34)", Read::Long);
    b.group = QStringLiteral("Brake");
    b.add("brake-ta", "Brake release delay", "brake_ta", 0, 65535, "ms", 0,
          "Wait between switching the motor current on and releasing the brake (5.35)", Read::Long);
    b.add("brake-tb", "Motion delay after brake release", "brake_tb", 0, 65535, "ms", 0,
          "Wait between releasing the brake and allowing motion (5.36)", Read::Long);
    b.add("brake-tc", "Current-off delay after braking", "brake_tc", 0, 65535, "ms", 0,
          "Wait between engaging the brake and switching the motor current off (5.37)", Read::Long);
}

void limitSwitches(Builder& b)
{
    b.group = QStringLiteral("Limit switches");
    b.choice("limit-switch-type", "External limit switch type", "e",
             {{"normally-closed", 0}, {"normally-open", 1}}, "normally-closed",
             "Switch between +5 V and input 6: a normally closed switch ('Oeffner') reads high "
             "until it is actuated (5.7)");
    // 5.6: one 16-bit mask 'l' with four groups in each of which exactly one bit is set.
    auto group = [&](const char* name, const char* label, qint64 mask, QList<qint64> bits,
                     const char* def, const char* desc) {
        QList<QPair<const char*, qint64>> entries = kSwitchNormal.mid(0, bits.size());
        for (int i = 0; i < bits.size(); ++i)
            entries[i].second = bits[i];
        ParamDef& d = b.choice(name, label, "l", entries, def, desc);
        d.fieldMask = mask;
    };
    group("limit-switch-behaviour-internal-reference", "Internal switch, reference run", 0x0003,
          {0x0001, 0x0002}, "free-backward",
          "Free travel after the encoder index in an internal reference run, relative to "
          "the run: backward leaves the mark again (5.6 bits 0-1)");
    group("limit-switch-behaviour-internal-normal", "Internal switch, normal run", 0x003C,
          {0x0004, 0x0008, 0x0010, 0x0020}, "ignore",
          "What the drive does when it reaches the encoder index during a normal run; useful "
          "when the motor must not turn more than one revolution (5.6 bits 2-5)");
    group("limit-switch-behaviour-external-reference", "External switch, reference run", 0x0600,
          {0x0200, 0x0400}, "free-backward",
          "Free travel after reaching the external switch in an external reference run, "
          "relative to the run: backward backs off the switch (5.6 bits 9-10)");
    group("limit-switch-behaviour-external-normal", "External switch, normal run", 0x7800,
          {0x0800, 0x1000, 0x2000, 0x4000}, "free-backward",
          "What the drive does when it reaches the external switch during a normal run; 'stop' "
          "limits the travel hard (5.6 bits 11-14)");
}

void encoder(Builder& b)
{
    b.group = QStringLiteral("Encoder & error correction");
    b.choice("error-correction-mode", "Error correction", "U",
             {{"off", 0}, {"after-move", 1}, {"during-move", 2}}, "after-move",
             "Position check by the encoder. Must be 'off' for motors without an encoder, or the "
             "drive keeps correcting. 'during-move' is not implemented by the firmware (5.9)");
    b.add("correction-record", "Correction record", "F", 1, 32, "", 1,
          "Record used for the correction run (5.10)");
    b.choice("encoder-direction", "Encoder direction", "q", {{"normal", 0}, {"reversed", 1}},
             "normal", "Reverses the counting direction of the encoder (5.11)");
    b.add("settle-time", "Settle time", "O", 0, 255, "x10 ms", 2,
          "Wait between the end of a run and the encoder check; the drive reports ready only "
          "after it (5.12)");
    b.add("max-encoder-deviation", "Max encoder deviation", "X", 0, 100, "steps", 2,
          "Allowed difference between demand and encoder position; must be above 0 for step "
          "modes finer than 1/10 (1.8 deg) or 1/5 (0.9 deg) (5.13)");
}

void inputsOutputs(Builder& b)
{
    b.group = QStringLiteral("Inputs & outputs");
    b.add("io-mask", "I/O used by firmware", "L", 0, 0x3003F, "bitmask", 0x3003F,
          "Bit set: the firmware uses the I/O; clear: free for the user. Bits 0-5 inputs 1-6, "
          "16-17 outputs 1-2. All bits are written at once (5.24)")
        .validBits = 0x3003F;
    b.add("io-polarity", "I/O polarity", "h", 0, 0x3003F, "bitmask", 0x3003F,
          "Bit set: normal polarity, clear: inverted. Bits 0-5 inputs 1-6, 16-17 outputs 1-2 "
          "(5.25)")
        .validBits = 0x3003F;
    b.add("input-interrupts", "Input interrupts", "k", 0, 0x3F, "bitmask", 0,
          "Interrupt on every edge of inputs 1-6 (bits 0-5); input 6 reacts to one edge only "
          "(5.26)")
        .validBits = 0x3F;
    b.add("input-interrupts-rising", "Interrupts on rising edge", "/", 0, 0x3F, "bitmask", 0,
          "Inputs (bits 0-5) whose interrupt reacts to rising edges (5.27)")
        .validBits = 0x3F;
    b.add("input-interrupts-falling", "Interrupts on falling edge", "\\", 0, 0x3F, "bitmask", 0,
          "Inputs (bits 0-5) whose interrupt reacts to falling edges (5.28)")
        .validBits = 0x3F;
    b.add("debounce-time", "Debounce time", "K", 0, 10, "ms", 0,
          "Wait after an input change until the signal counts as stable (5.29)");
    ParamDef& out = b.add("outputs", "Outputs", "Y", 0, 0x30000, "bitmask", 0,
                          "Output 1 = bit 16 (65536), output 2 = bit 17 (131072); only outputs "
                          "freed with io-mask follow (5.30)");
    out.validBits = 0x30000;
    out.fieldMask = 0x30000;
    ParamDef& in = b.add("input-states", "Input states", "Y", 0, 0x7F, "bitmask", 0,
                         "Inputs 1-6 (bits 0-5); bit 6 is 0 while the encoder is at its index "
                         "mark (read with ZY, 5.30)");
    in.fieldMask = 0x7F;
    in.spec.writable = false;
}

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
} // namespace

const QList<ParamDef>& parameterTable()
{
    static const QList<ParamDef> table = [] {
        Builder b;
        motor(b);
        limitSwitches(b);
        encoder(b);
        inputsOutputs(b);
        record(b);
        analog(b);
        closedLoop(b);
        readOnly(b);
        return b.defs;
    }();
    return table;
}

const ParamDef* findParam(const QString& name)
{
    for (const ParamDef& d : parameterTable()) {
        if (d.spec.name == name)
            return &d;
    }
    return nullptr;
}

const ParamDef* findRecordField(char cmd)
{
    for (const ParamDef& d : parameterTable()) {
        if (d.record && d.cmd.size() == 1 && d.cmd.at(0) == cmd)
            return &d;
    }
    return nullptr;
}

ParameterSchema parameterSchema()
{
    QList<ParameterSpec> specs;
    for (const ParamDef& d : parameterTable())
        specs << d.spec;
    return ParameterSchema(specs);
}

std::optional<qint64> toWire(const ParamDef& def, const QVariant& value)
{
    const QVariant v = ParameterSchema().normalise(def.spec, value);
    if (!v.isValid())
        return std::nullopt;
    switch (def.spec.type) {
    case ParameterType::Integer:
        return v.toLongLong();
    case ParameterType::Boolean:
        return v.toBool() ? 1 : 0;
    case ParameterType::Choice: {
        const int i = int(def.spec.choices.indexOf(v.toString()));
        if (i < 0)
            return std::nullopt;
        return def.choiceValues.at(i);
    }
    }
    return std::nullopt;
}

QVariant fromWire(const ParamDef& def, qint64 wire)
{
    const qint64 w = def.fieldMask ? (wire & def.fieldMask) : wire;
    switch (def.spec.type) {
    case ParameterType::Integer:
        return w;
    case ParameterType::Boolean:
        return w != 0;
    case ParameterType::Choice: {
        const int i = int(def.choiceValues.indexOf(w));
        if (i >= 0)
            return def.spec.choices.at(i);
        return QStringLiteral("invalid (%1)").arg(w);
    }
    }
    return {};
}

QString extraValidation(const ParamDef& def, const QVariant& value)
{
    if (!def.validBits)
        return {};
    const auto wire = toWire(def, value);
    if (wire && (*wire & ~def.validBits)) {
        return QStringLiteral("%1: bits 0x%2 are not defined by the manual (allowed mask 0x%3); "
                              "the drive would discard the whole mask")
            .arg(def.spec.name)
            .arg(*wire & ~def.validBits, 0, 16)
            .arg(def.validBits, 0, 16);
    }
    return {};
}

} // namespace stepdeck::nanotec
