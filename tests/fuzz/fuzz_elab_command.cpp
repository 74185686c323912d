// libFuzzer target: the E-LAB command decoder (device side: simulator, traffic console).
// Invariants: one chunk, any split and byte by byte decode alike; every byte is in a command's
// raw, buffered, or one of the tolerated blanks; the buffer stays within one frame; every
// valid command re-encodes to its own bytes through the host's encoders (hex upper-case;
// switch polarities and coolant only where the byte is one of the two levels the encoder
// writes, $FF or $00); every host encoder's output decodes to the values it was given.
#include "FuzzSupport.h"
#include "protocols/elab/ElabCodec.h"
#include <optional>

using namespace stepdeck::elab;

namespace {
QString describe(const Command& c)
{
    return QStringLiteral("%1 %2 v%3:%4,%5,%6 s%7 %8 [%9] %10")
        .arg(int(c.code))
        .arg(QChar(char(c.ramp)))
        .arg(c.valueCount)
        .arg(c.values[0])
        .arg(c.values[1])
        .arg(c.values[2])
        .arg(c.stepByte)
        .arg(c.valid)
        .arg(fuzz::hex(c.raw), c.error);
}

bool same(const Command& a, const Command& b)
{
    return a.code == b.code && a.ramp == b.ramp && a.valueCount == b.valueCount &&
           a.values == b.values && a.stepByte == b.stepByte && a.valid == b.valid &&
           a.raw == b.raw && a.error == b.error;
}

QStringList describeAll(const QList<Command>& commands)
{
    QStringList out;
    for (const Command& c : commands)
        out << describe(c);
    return out;
}

struct Run
{
    QList<Command> commands;
    int buffered = 0;
    qint64 unframed = 0;
};

Run run(const QList<QByteArray>& chunks)
{
    CommandDecoder decoder;
    Run r;
    r.commands =
        fuzz::decodeChunks<CommandDecoder, Command>(decoder, chunks, [](const CommandDecoder& d) {
            FUZZ_CHECK(d.buffered() <= CommandDecoder::kMaxFrame, QString::number(d.buffered()));
        });
    r.buffered = decoder.buffered();
    r.unframed = decoder.unframedBytes();
    return r;
}

template <typename T> Triple<T> values(const Command& c)
{
    return {T(c.values[0]), T(c.values[1]), T(c.values[2])};
}

// $FF / $00 as the encoders write booleans; nullopt for any other byte.
std::optional<Triple<bool>> levels(const Command& c, int count)
{
    Triple<bool> out{};
    for (int i = 0; i < count; ++i) {
        if (c.values[size_t(i)] != 0 && c.values[size_t(i)] != 0xFF)
            return std::nullopt;
        out[size_t(i)] = c.values[size_t(i)] == 0xFF;
    }
    return out;
}

// The host encoder's bytes for a decoded command; nullopt where no encoder writes it.
std::optional<QByteArray> reencode(const Command& c)
{
    switch (c.code) {
    case ctrl::DC4:
        return encode::jogSpeed(values<qint16>(c));
    case ctrl::US:
        return encode::referenceMove(values<qint16>(c));
    case ctrl::CAN:
        return encode::velocityMove(values<qint16>(c));
    case ctrl::FS:
        return encode::feedSpeed(values<quint16>(c));
    case ctrl::ESC:
        return encode::ramp(c.ramp, values<quint16>(c));
    case ctrl::EOT:
        return encode::fastMoveXYZ(values<qint32>(c));
    case ctrl::FF:
        return encode::fastMoveXY(qint32(c.values[0]), qint32(c.values[1]));
    case ctrl::BS:
        return encode::fastMoveZ(qint32(c.values[0]));
    case ctrl::VT:
        return encode::feedStepsZ(qint32(c.values[0]));
    case ctrl::EM:
        return encode::feedStepsX(qint32(c.values[0]));
    case ctrl::SUB:
        return encode::feedStepsY(qint32(c.values[0]));
    case ctrl::SOH:
        return encode::spindleRpm(quint32(c.values[0]));
    case ctrl::STX:
        return encode::drivePower(quint8(c.values[0]));
    case ctrl::DC2:
        return encode::feedStep(c.stepByte);
    case ctrl::SO:
        if (const auto l = levels(c, 3))
            return encode::limitSwitchPolarity(*l);
        return std::nullopt;
    case ctrl::DLE:
        if (const auto l = levels(c, 3))
            return encode::referenceSwitchPolarity(*l);
        return std::nullopt;
    case ctrl::SI:
        if (const auto l = levels(c, 1))
            return encode::coolant((*l)[0]);
        return std::nullopt;
    default:
        return QByteArray(1, c.code); // the one-byte commands
    }
}

void expectOne(const QByteArray& bytes, char code, const std::array<qint64, 3>& want, int count)
{
    CommandDecoder decoder;
    const QList<Command> c = decoder.feed(bytes);
    FUZZ_CHECK(c.size() == 1 && decoder.buffered() == 0, describeAll(c).join('|'));
    FUZZ_CHECK(c[0].valid && c[0].code == code && c[0].valueCount == count, describe(c[0]));
    for (int i = 0; i < count; ++i)
        FUZZ_CHECK(c[0].values[size_t(i)] == want[size_t(i)], describe(c[0]));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const Triple<qint16> s16{qint16(in.next(2)), qint16(in.next(2)), qint16(in.next(2))};
    const Triple<quint16> u16{quint16(in.next(2)), quint16(in.next(2)), quint16(in.next(2))};
    const Triple<qint32> s32{qint32(in.next(4)), qint32(in.next(4)), qint32(in.next(4))};
    const auto wide = [](auto t) { return std::array<qint64, 3>{t[0], t[1], t[2]}; };
    expectOne(encode::jogSpeed(s16), ctrl::DC4, wide(s16), 3);
    expectOne(encode::velocityMove(s16), ctrl::CAN, wide(s16), 3);
    expectOne(encode::referenceMove(s16), ctrl::US, wide(s16), 3);
    expectOne(encode::feedSpeed(u16), ctrl::FS, wide(u16), 3);
    expectOne(encode::ramp(RampKind::MaxSpeed, u16), ctrl::ESC, wide(u16), 3);
    expectOne(encode::fastMoveXYZ(s32), ctrl::EOT, wide(s32), 3);
    expectOne(encode::fastMoveXY(s32[0], s32[1]), ctrl::FF, wide(s32), 2);
    expectOne(encode::fastMoveZ(s32[2]), ctrl::BS, {s32[2], 0, 0}, 1);
    expectOne(encode::feedStepsX(s32[0]), ctrl::EM, {s32[0], 0, 0}, 1);
    expectOne(encode::feedStepsY(s32[1]), ctrl::SUB, {s32[1], 0, 0}, 1);
    expectOne(encode::feedStepsZ(s32[2]), ctrl::VT, {s32[2], 0, 0}, 1);
    expectOne(encode::spindleRpm(quint32(s32[0])), ctrl::SOH, {qint64(quint32(s32[0])), 0, 0}, 1);
    expectOne(encode::drivePower(quint8(u16[0])), ctrl::STX, {qint64(quint8(u16[0])), 0, 0}, 1);
    const Triple<bool> flags{(u16[1] & 1) != 0, (u16[1] & 2) != 0, (u16[1] & 4) != 0};
    const auto level = [](bool b) { return qint64(b ? 0xFF : 0); };
    expectOne(encode::limitSwitchPolarity(flags), ctrl::SO,
              {level(flags[0]), level(flags[1]), level(flags[2])}, 3);
    expectOne(encode::coolant(flags[0]), ctrl::SI, {level(flags[0]), 0, 0}, 1);
    const quint8 step =
        encodeStepByte(int(u16[2] % 3) - 1, int(u16[2] / 3 % 3) - 1, int(u16[2] / 9 % 3) - 1);
    CommandDecoder decoder;
    const QList<Command> c = decoder.feed(encode::feedStep(step));
    FUZZ_CHECK(c.size() == 1 && c[0].valid && c[0].stepByte == step, describeAll(c).join('|'));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    const Run whole = run({in});
    for (const Run& other : {run(fuzz::split(in)), run(fuzz::bytes(in))}) {
        FUZZ_CHECK(fuzz::sameLists(other.commands, whole.commands, same),
                   "split decodes differently: " + describeAll(whole.commands).join('|'));
        FUZZ_CHECK(other.buffered == whole.buffered && other.unframed == whole.unframed,
                   "split leaves other state");
    }
    qsizetype accounted = whole.buffered + whole.unframed;
    for (const Command& c : whole.commands) {
        accounted += c.raw.size();
        FUZZ_CHECK(!c.raw.isEmpty() && c.raw.size() <= CommandDecoder::kMaxFrame, describe(c));
        FUZZ_CHECK(c.valid == c.error.isEmpty(), describe(c));
        if (!c.valid)
            continue;
        // Hex digits may arrive in lower case; a DC2 step byte is data, compared as it is.
        const QByteArray own = c.code == ctrl::DC2 ? c.raw : c.raw.toUpper();
        if (const auto bytes = reencode(c))
            FUZZ_CHECK(*bytes == own, describe(c) + " -> " + fuzz::hex(*bytes));
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
