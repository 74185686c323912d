// libFuzzer target: the Nanotec command decoder (device side: simulator). Invariants: one
// chunk, any split and byte by byte decode alike; every byte is in a command's raw, buffered,
// or outside frames (before a '#', the tail of an overlong frame); the buffer stays within one
// frame; every valid command the host may send re-encodes through encode::command to its own
// bytes when its address is written without leading zeros, and to an equal command otherwise;
// every encoder's output decodes to what it was given.
#include "FuzzSupport.h"
#include "protocols/nanotec/NanotecCodec.h"

using namespace stepdeck::nanotec;

namespace {
QString meaning(const Command& c)
{
    return QStringLiteral("%1 @%2 %3 %4")
        .arg(c.broadcast)
        .arg(c.address)
        .arg(fuzz::hex(c.body))
        .arg(c.valid);
}

QString describe(const Command& c)
{
    return meaning(c) + QStringLiteral(" [%1] %2").arg(fuzz::hex(c.raw), c.error);
}

bool sameMeaning(const Command& a, const Command& b)
{
    return a.broadcast == b.broadcast && a.address == b.address && a.body == b.body &&
           a.valid == b.valid;
}

bool same(const Command& a, const Command& b)
{
    return sameMeaning(a, b) && a.raw == b.raw && a.error == b.error;
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

void checkReencodes(const Command& c)
{
    const QByteArray bytes = encode::command(c.broadcast ? kBroadcast : c.address, c.body);
    if (bytes.isEmpty()) {
        FUZZ_CHECK(!forbiddenReason(c.body).isEmpty(), describe(c)); // never sent by the host
        return;
    }
    CommandDecoder decoder;
    const QList<Command> again = decoder.feed(bytes);
    FUZZ_CHECK(again.size() == 1 && sameMeaning(again[0], c),
               describe(c) + " -> " + describeAll(again).join('|'));
    const QByteArray addressText = c.raw.mid(1, c.raw.size() - 2 - c.body.size());
    if (c.broadcast || addressText == QByteArray::number(c.address))
        FUZZ_CHECK(bytes == c.raw, describe(c) + " -> " + fuzz::hex(bytes));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const int address = kMinAddress + int(in.next(1) % kMaxAddress);
    const int record = 1 + int(in.next(1) % kRecordCount);
    const qint64 value = qint64(in.next(4)) - 2147483648ll;
    const QList<QPair<QByteArray, QByteArray>> cases{
        {encode::command(address, "A"), "A"},
        {encode::command(address, "o", value), "o" + QByteArray::number(value)},
        {encode::read(address, "s", record), "Z" + QByteArray::number(record) + "s"},
        {encode::readRecord(address, record), "Z" + QByteArray::number(record) + "|"},
        {encode::readErrorMemory(address, record), "ZE" + QByteArray::number(record)},
        {encode::longRead(address, "CL_motor_pp"), ":CL_motor_pp"},
        {encode::longWrite(address, "CL_motor_pp", value),
         ":CL_motor_pp=" + QByteArray::number(value)},
        {encode::command(kBroadcast, "S"), "S"},
    };
    for (const auto& [frame, body] : cases) {
        CommandDecoder decoder;
        const QList<Command> c = decoder.feed(frame);
        FUZZ_CHECK(c.size() == 1 && c[0].valid && c[0].body == body,
                   fuzz::hex(frame) + " -> " + describeAll(c).join('|'));
        FUZZ_CHECK(c[0].broadcast ? body == "S" : c[0].address == address, describe(c[0]));
    }
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
        FUZZ_CHECK(!c.raw.isEmpty() && c.raw.size() <= CommandDecoder::kMaxFrame + 1, describe(c));
        FUZZ_CHECK(c.valid == c.error.isEmpty(), describe(c));
        if (c.valid)
            checkReencodes(c);
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
