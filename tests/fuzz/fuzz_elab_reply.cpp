// libFuzzer target: the E-LAB reply decoder (host side, ElabCodec.h). Invariants: one chunk,
// any split and byte by byte decode alike; every byte is in a frame's raw or still buffered;
// the buffer never exceeds one frame; every valid frame re-encodes to its own bytes (hex
// digits upper-case, as the manual writes them); every reply encoder's output decodes to
// the values it was given.
#include "FuzzSupport.h"
#include "protocols/elab/ElabCodec.h"

using namespace stepdeck::elab;

namespace {
QString describe(const Reply& r)
{
    return QStringLiteral("%1 m%2 a%3 t%4 p%5,%6,%7 [%8] %9")
        .arg(int(r.kind))
        .arg(r.machineState)
        .arg(r.axeState)
        .arg(r.temperature)
        .arg(r.positions[0])
        .arg(r.positions[1])
        .arg(r.positions[2])
        .arg(fuzz::hex(r.raw), r.error);
}

bool same(const Reply& a, const Reply& b)
{
    return a.kind == b.kind && a.machineState == b.machineState && a.axeState == b.axeState &&
           a.temperature == b.temperature && a.positions == b.positions && a.raw == b.raw &&
           a.error == b.error;
}

QStringList describeAll(const QList<Reply>& replies)
{
    QStringList out;
    for (const Reply& r : replies)
        out << describe(r);
    return out;
}

QList<Reply> run(const QList<QByteArray>& chunks, int* buffered)
{
    ReplyDecoder decoder;
    const QList<Reply> out =
        fuzz::decodeChunks<ReplyDecoder, Reply>(decoder, chunks, [](const ReplyDecoder& d) {
            FUZZ_CHECK(d.buffered() <= ReplyDecoder::kMaxFrame, QString::number(d.buffered()));
        });
    *buffered = decoder.buffered();
    return out;
}

// The bytes a valid reply re-encodes to; empty for Invalid.
QByteArray reencode(const Reply& r)
{
    switch (r.kind) {
    case Reply::Kind::Ack:
        return QByteArray(1, ctrl::ACK);
    case Reply::Kind::Nak:
        return QByteArray(1, ctrl::NAK);
    case Reply::Kind::XOn:
        return QByteArray(1, ctrl::XON);
    case Reply::Kind::XOff:
        return QByteArray(1, ctrl::XOFF);
    case Reply::Kind::MachineState:
        return encodeReply::machineState(r.machineState);
    case Reply::Kind::AxeState:
        return encodeReply::axeState(r.axeState);
    case Reply::Kind::Temperature:
        return encodeReply::temperature(r.temperature);
    case Reply::Kind::RelPosition:
        return encodeReply::relPosition(r.positions);
    case Reply::Kind::Invalid:
        break;
    }
    return {};
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const auto word = quint16(in.next(2));
    const auto byte = quint8(in.next(1));
    const auto temp = quint8(in.next(1));
    const Triple<qint32> pos{qint32(in.next(4)), qint32(in.next(4)), qint32(in.next(4))};
    ReplyDecoder decoder;
    const QList<Reply> r =
        decoder.feed(encodeReply::machineState(word) + encodeReply::axeState(byte) +
                     encodeReply::temperature(temp) + encodeReply::relPosition(pos));
    FUZZ_CHECK(r.size() == 4 && decoder.buffered() == 0, describeAll(r).join('|'));
    FUZZ_CHECK(r[0].kind == Reply::Kind::MachineState && r[0].machineState == word, describe(r[0]));
    FUZZ_CHECK(r[1].kind == Reply::Kind::AxeState && r[1].axeState == byte, describe(r[1]));
    FUZZ_CHECK(r[2].kind == Reply::Kind::Temperature && r[2].temperature == temp, describe(r[2]));
    FUZZ_CHECK(r[3].kind == Reply::Kind::RelPosition && r[3].positions == pos, describe(r[3]));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    int wholeBuffered = 0;
    int splitBuffered = 0;
    int byteBuffered = 0;
    const QList<Reply> whole = run({in}, &wholeBuffered);
    FUZZ_CHECK(fuzz::sameLists(run(fuzz::split(in), &splitBuffered), whole, same),
               "split decodes differently: " + describeAll(whole).join('|'));
    FUZZ_CHECK(fuzz::sameLists(run(fuzz::bytes(in), &byteBuffered), whole, same),
               "byte by byte decodes differently: " + describeAll(whole).join('|'));
    FUZZ_CHECK(splitBuffered == wholeBuffered && byteBuffered == wholeBuffered, "buffered differs");

    qsizetype accounted = wholeBuffered;
    for (const Reply& r : whole) {
        accounted += r.raw.size();
        FUZZ_CHECK(!r.raw.isEmpty() && r.raw.size() <= ReplyDecoder::kMaxFrame, describe(r));
        FUZZ_CHECK((r.kind == Reply::Kind::Invalid) == !r.error.isEmpty(), describe(r));
        if (r.kind != Reply::Kind::Invalid)
            FUZZ_CHECK(reencode(r) == r.raw.toUpper(),
                       describe(r) + " -> " + fuzz::hex(reencode(r)));
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
