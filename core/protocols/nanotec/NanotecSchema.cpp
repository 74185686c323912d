// The whole SMCI33/SMCI47-S command reference as typed parameters. Every parameter belongs to
// one drive, and each drive is one axis, so all of them are per axis.
#include "NanotecSchema.h"
#include "NanotecSchemaBuilder.h"

namespace stepdeck::nanotec {

namespace schema {

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
    ParamDef& autoStatus = b.boolean(
        "auto-status", "Send status after moves", "J", false,
        "The drive sends its status ('j') by itself at the end of every move (5.31). StepDeck "
        "polls the bus and switches this off when it connects");
    autoStatus.spec.warning = QStringLiteral(
        "On a half-duplex RS485 bus that is being polled, a status the drive sends by itself "
        "collides with the poll of another drive. StepDeck switches it off again on the next "
        "connect.");
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

} // namespace schema

const QList<ParamDef>& parameterTable()
{
    static const QList<ParamDef> table = [] {
        using namespace schema;
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
