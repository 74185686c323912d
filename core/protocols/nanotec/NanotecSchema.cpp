// The whole SMCI33/SMCI47-S command reference as typed parameters. Every parameter belongs to
// one drive, and each drive is one axis, so all of them are per axis.
#include "NanotecSchema.h"
#include "NanotecSchemaBuilder.h"

namespace stepdeck::nanotec {

namespace schema {

const QList<QPair<const char*, qint64>> kSwitchNormal{
    {QT_TRANSLATE_NOOP("Parameters", "free-forward"), 0},
    {QT_TRANSLATE_NOOP("Parameters", "free-backward"), 0},
    {QT_TRANSLATE_NOOP("Parameters", "stop"), 0},
    {QT_TRANSLATE_NOOP("Parameters", "ignore"), 0}};

void motor(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Motor"));
    b.add("phase-current", QT_TRANSLATE_NOOP("Parameters", "Phase current"), "i", 0, 150,
          QT_TRANSLATE_NOOP("Parameters", "%"), 50,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Motor current relative to the drive's full scale; values above 100 should be "
              "avoided (5.1)"));
    b.add("idle-current", QT_TRANSLATE_NOOP("Parameters", "Idle current"), "r", 0, 150,
          QT_TRANSLATE_NOOP("Parameters", "%"), 25,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Current at standstill, relative to full scale (not to the phase current); values "
              "above 100 should be avoided (5.2)"));
    b.choice("step-mode", QT_TRANSLATE_NOOP("Parameters", "Step mode"), "g",
             {{"1", 1},
              {"2", 2},
              {"4", 4},
              {"5", 5},
              {"8", 8},
              {"10", 10},
              {"16", 16},
              {"32", 32},
              {"64", 64},
              {QT_TRANSLATE_NOOP("Parameters", "adaptive"), 255}},
             "2",
             QT_TRANSLATE_NOOP(
                 "Parameters",
                 "Microsteps per full step; 'adaptive' selects the adaptive step mode (5.3)"));
    b.choice("step-angle", QT_TRANSLATE_NOOP("Parameters", "Step angle"), "a",
             {{"0.9", 9}, {"1.8", 18}}, "1.8",
             QT_TRANSLATE_NOOP(
                 "Parameters",
                 "Full-step angle of the motor in degrees, needed to convert encoder positions; "
                 "changes cl-motor-pole-pairs as well (5.8, 8.6)"))
        .spec.unit = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "deg"));
    b.choice(
        "motor-mode", QT_TRANSLATE_NOOP("Parameters", "Motor mode"), "!",
        {{QT_TRANSLATE_NOOP("Parameters", "positioning"), 1},
         {QT_TRANSLATE_NOOP("Parameters", "speed"), 2},
         {QT_TRANSLATE_NOOP("Parameters", "flag-positioning"), 3},
         {QT_TRANSLATE_NOOP("Parameters", "clock-direction"), 4},
         {QT_TRANSLATE_NOOP("Parameters", "analog"), 5},
         {QT_TRANSLATE_NOOP("Parameters", "joystick"), 6},
         // 8.1: the closed-loop reference run and the calibration run are modes as well.
         {QT_TRANSLATE_NOOP("Parameters", "closed-loop-reference"), 8},
         {QT_TRANSLATE_NOOP("Parameters", "calibration"), 101}},
        "positioning",
        QT_TRANSLATE_NOOP(
            "Parameters",
            "Operating mode (5.5, 8.1). Moves, jog and reference runs switch the mode themselves; "
            "the closed-loop workflow runs calibration and closed-loop-reference and sets the "
            "mode of before again afterwards."));
    ParamDef& addr =
        b.add("motor-address", QT_TRANSLATE_NOOP("Parameters", "Motor address"), "m", 1, 254, "", 1,
              QT_TRANSLATE_NOOP("Parameters", "RS485 bus address of the drive (5.4)"));
    addr.spec.warning = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "Communication continues at the new address. It must not be used by another drive on "
        "the bus, or no communication is possible any more (manual 5.4)."));
    b.add("backlash", QT_TRANSLATE_NOOP("Parameters", "Backlash"), "z", 0, 9999,
          QT_TRANSLATE_NOOP("Parameters", "steps"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Steps made on a direction change before the position counts, to take up gear play "
              "(5.33)"));
    ParamDef& autoStatus = b.boolean(
        "auto-status", QT_TRANSLATE_NOOP("Parameters", "Send status after moves"), "J", false,
        QT_TRANSLATE_NOOP(
            "Parameters",
            "The drive sends its status ('j') by itself at the end of every move (5.31). StepDeck "
            "polls the bus and switches this off when it connects"));
    autoStatus.spec.warning = QStringLiteral(QT_TRANSLATE_NOOP(
        "Parameters",
        "On a half-duplex RS485 bus that is being polled, a status the drive sends by itself "
        "collides with the poll of another drive. StepDeck switches it off again on the next "
        "connect."));
    b.choice("ramp-mode", QT_TRANSLATE_NOOP("Parameters", "Ramp shape"), "CL_ramp_mode",
             {{QT_TRANSLATE_NOOP("Parameters", "trapezoid"), 0},
              {QT_TRANSLATE_NOOP("Parameters", "sinus"), 1}},
             "trapezoid", QT_TRANSLATE_NOOP("Parameters", "Ramp of the positioning mode (5.34)"),
             Read::Long);
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Brake"));
    b.add("brake-ta", QT_TRANSLATE_NOOP("Parameters", "Brake release delay"), "brake_ta", 0, 65535,
          QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Wait between switching the motor current on and releasing the brake (5.35)"),
          Read::Long);
    b.add("brake-tb", QT_TRANSLATE_NOOP("Parameters", "Motion delay after brake release"),
          "brake_tb", 0, 65535, QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP("Parameters",
                            "Wait between releasing the brake and allowing motion (5.36)"),
          Read::Long);
    b.add("brake-tc", QT_TRANSLATE_NOOP("Parameters", "Current-off delay after braking"),
          "brake_tc", 0, 65535, QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Wait between engaging the brake and switching the motor current off (5.37)"),
          Read::Long);
}

void limitSwitches(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Limit switches"));
    b.choice("limit-switch-type", QT_TRANSLATE_NOOP("Parameters", "External limit switch type"),
             "e",
             {{QT_TRANSLATE_NOOP("Parameters", "normally-closed"), 0},
              {QT_TRANSLATE_NOOP("Parameters", "normally-open"), 1}},
             "normally-closed",
             QT_TRANSLATE_NOOP(
                 "Parameters",
                 "Switch between +5 V and input 6: a normally closed switch ('Oeffner') reads high "
                 "until it is actuated (5.7)"));
    // 5.6: one 16-bit mask 'l' with four groups in each of which exactly one bit is set.
    auto group = [&](const char* name, const char* label, qint64 mask, QList<qint64> bits,
                     const char* def, const char* desc) {
        QList<QPair<const char*, qint64>> entries = kSwitchNormal.mid(0, bits.size());
        for (int i = 0; i < bits.size(); ++i)
            entries[i].second = bits[i];
        ParamDef& d = b.choice(name, label, "l", entries, def, desc);
        d.fieldMask = mask;
    };
    group("limit-switch-behaviour-internal-reference",
          QT_TRANSLATE_NOOP("Parameters", "Internal switch, reference run"), 0x0003,
          {0x0001, 0x0002}, "free-backward",
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Free travel after the encoder index in an internal reference run, relative to "
              "the run: backward leaves the mark again (5.6 bits 0-1)"));
    group("limit-switch-behaviour-internal-normal",
          QT_TRANSLATE_NOOP("Parameters", "Internal switch, normal run"), 0x003C,
          {0x0004, 0x0008, 0x0010, 0x0020}, "ignore",
          QT_TRANSLATE_NOOP(
              "Parameters",
              "What the drive does when it reaches the encoder index during a normal run; useful "
              "when the motor must not turn more than one revolution (5.6 bits 2-5)"));
    group("limit-switch-behaviour-external-reference",
          QT_TRANSLATE_NOOP("Parameters", "External switch, reference run"), 0x0600,
          {0x0200, 0x0400}, "free-backward",
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Free travel after reaching the external switch in an external reference run, "
              "relative to the run: backward backs off the switch (5.6 bits 9-10)"));
    group("limit-switch-behaviour-external-normal",
          QT_TRANSLATE_NOOP("Parameters", "External switch, normal run"), 0x7800,
          {0x0800, 0x1000, 0x2000, 0x4000}, "free-backward",
          QT_TRANSLATE_NOOP(
              "Parameters",
              "What the drive does when it reaches the external switch during a normal run; 'stop' "
              "limits the travel hard (5.6 bits 11-14)"));
}

void encoder(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Encoder & error correction"));
    b.choice(
        "error-correction-mode", QT_TRANSLATE_NOOP("Parameters", "Error correction"), "U",
        {{QT_TRANSLATE_NOOP("Parameters", "off"), 0},
         {QT_TRANSLATE_NOOP("Parameters", "after-move"), 1},
         {QT_TRANSLATE_NOOP("Parameters", "during-move"), 2}},
        "after-move",
        QT_TRANSLATE_NOOP(
            "Parameters",
            "Position check by the encoder. Must be 'off' for motors without an encoder, or the "
            "drive keeps correcting. 'during-move' is not implemented by the firmware (5.9)"));
    b.add("correction-record", QT_TRANSLATE_NOOP("Parameters", "Correction record"), "F", 1, 32, "",
          1, QT_TRANSLATE_NOOP("Parameters", "Record used for the correction run (5.10)"));
    b.choice(
        "encoder-direction", QT_TRANSLATE_NOOP("Parameters", "Encoder direction"), "q",
        {{QT_TRANSLATE_NOOP("Parameters", "normal"), 0},
         {QT_TRANSLATE_NOOP("Parameters", "reversed"), 1}},
        "normal",
        QT_TRANSLATE_NOOP("Parameters", "Reverses the counting direction of the encoder (5.11)"));
    b.add("settle-time", QT_TRANSLATE_NOOP("Parameters", "Settle time"), "O", 0, 255,
          QT_TRANSLATE_NOOP("Parameters", "x10 ms"), 2,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Wait between the end of a run and the encoder check; the drive reports ready only "
              "after it (5.12)"));
    b.add("max-encoder-deviation", QT_TRANSLATE_NOOP("Parameters", "Max encoder deviation"), "X", 0,
          100, QT_TRANSLATE_NOOP("Parameters", "steps"), 2,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Allowed difference between demand and encoder position; must be above 0 for step "
              "modes finer than 1/10 (1.8 deg) or 1/5 (0.9 deg) (5.13)"));
}

void inputsOutputs(Builder& b)
{
    b.group = QString::fromUtf8(QT_TRANSLATE_NOOP("Parameters", "Inputs & outputs"));
    b.add("io-mask", QT_TRANSLATE_NOOP("Parameters", "I/O used by firmware"), "L", 0, 0x3003F,
          QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0x3003F,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Bit set: the firmware uses the I/O; clear: free for the user. Bits 0-5 inputs 1-6, "
              "16-17 outputs 1-2. All bits are written at once (5.24)"))
        .validBits = 0x3003F;
    b.add("io-polarity", QT_TRANSLATE_NOOP("Parameters", "I/O polarity"), "h", 0, 0x3003F,
          QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0x3003F,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Bit set: normal polarity, clear: inverted. Bits 0-5 inputs 1-6, 16-17 outputs 1-2 "
              "(5.25)"))
        .validBits = 0x3003F;
    b.add("input-interrupts", QT_TRANSLATE_NOOP("Parameters", "Input interrupts"), "k", 0, 0x3F,
          QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
          QT_TRANSLATE_NOOP(
              "Parameters",
              "Interrupt on every edge of inputs 1-6 (bits 0-5); input 6 reacts to one edge only "
              "(5.26)"))
        .validBits = 0x3F;
    b.add("input-interrupts-rising", QT_TRANSLATE_NOOP("Parameters", "Interrupts on rising edge"),
          "/", 0, 0x3F, QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
          QT_TRANSLATE_NOOP("Parameters",
                            "Inputs (bits 0-5) whose interrupt reacts to rising edges (5.27)"))
        .validBits = 0x3F;
    b.add("input-interrupts-falling", QT_TRANSLATE_NOOP("Parameters", "Interrupts on falling edge"),
          "\\", 0, 0x3F, QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
          QT_TRANSLATE_NOOP("Parameters",
                            "Inputs (bits 0-5) whose interrupt reacts to falling edges (5.28)"))
        .validBits = 0x3F;
    b.add("debounce-time", QT_TRANSLATE_NOOP("Parameters", "Debounce time"), "K", 0, 10,
          QT_TRANSLATE_NOOP("Parameters", "ms"), 0,
          QT_TRANSLATE_NOOP("Parameters",
                            "Wait after an input change until the signal counts as stable (5.29)"));
    ParamDef& out = b.add(
        "outputs", QT_TRANSLATE_NOOP("Parameters", "Outputs"), "Y", 0, 0x30000,
        QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
        QT_TRANSLATE_NOOP("Parameters",
                          "Output 1 = bit 16 (65536), output 2 = bit 17 (131072); only outputs "
                          "freed with io-mask follow (5.30)"));
    out.validBits = 0x30000;
    out.fieldMask = 0x30000;
    ParamDef& in = b.add(
        "input-states", QT_TRANSLATE_NOOP("Parameters", "Input states"), "Y", 0, 0x7F,
        QT_TRANSLATE_NOOP("Parameters", "bitmask"), 0,
        QT_TRANSLATE_NOOP("Parameters",
                          "Inputs 1-6 (bits 0-5); bit 6 is 0 while the encoder is at its index "
                          "mark (read with ZY, 5.30)"));
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
