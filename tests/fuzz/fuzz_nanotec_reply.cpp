// libFuzzer target: the Nanotec reply decoder (host side, NanotecCodec.h). Invariants: one
// chunk, any split and byte by byte decode alike; every byte is in a reply's raw, buffered,
// or a terminator/filler/dropped overlong tail (unframedBytes); the buffer stays within one
// frame; every valid reply re-encodes: its canonical form (3-digit address, or the plain one
// of long replies; values without '+' except where the manual writes signs: records, long
// reads, error slots) decodes to the same reply and is a fixed point; record strings carry
// only section 4's settings; every encoder's output decodes to the values it was given.
#include "FuzzSupport.h"
#include "protocols/nanotec/NanotecCodec.h"

using namespace stepdeck::nanotec;

namespace {
// Everything a reply means (not how it was written: raw and text are left out).
QString meaning(const Reply& r)
{
    QStringList fields;
    for (const auto& f : r.recordData.fields)
        fields << QStringLiteral("%1%2").arg(QChar(f.first)).arg(f.second);
    return QStringLiteral("%1 @%2 %3 v%4 rec%5 idx%6 %7 {%8} fw[%9|%10|%11|%12]%13")
        .arg(int(r.kind))
        .arg(r.address)
        .arg(QString::fromLatin1(r.key))
        .arg(r.value ? QString::number(*r.value) : QStringLiteral("-"))
        .arg(r.record)
        .arg(r.index)
        .arg(r.assignment)
        .arg(fields.join(','))
        .arg(r.firmware.hardware, r.firmware.interface, r.firmware.date, r.firmware.text)
        .arg(r.kind == Reply::Kind::HostEcho ? fuzz::hex(r.raw) : QString());
}

bool sameMeaning(const Reply& a, const Reply& b)
{
    return a.kind == b.kind && a.address == b.address && a.key == b.key && a.value == b.value &&
           a.record == b.record && a.index == b.index && a.assignment == b.assignment &&
           a.recordData.record == b.recordData.record &&
           a.recordData.fields == b.recordData.fields &&
           a.firmware.hardware == b.firmware.hardware &&
           a.firmware.interface == b.firmware.interface && a.firmware.date == b.firmware.date &&
           a.firmware.text == b.firmware.text &&
           (a.kind != Reply::Kind::HostEcho || a.raw == b.raw);
}

bool same(const Reply& a, const Reply& b)
{
    return sameMeaning(a, b) && a.text == b.text && a.raw == b.raw && a.error == b.error;
}

QString describe(const Reply& r)
{
    return meaning(r) + QStringLiteral(" [%1] %2").arg(fuzz::hex(r.raw), r.error);
}

QStringList describeAll(const QList<Reply>& replies)
{
    QStringList out;
    for (const Reply& r : replies)
        out << describe(r);
    return out;
}

struct Run
{
    QList<Reply> replies;
    int buffered = 0;
    qint64 unframed = 0;
};

Run run(const QList<QByteArray>& chunks)
{
    ReplyDecoder decoder;
    Run r;
    r.replies = fuzz::decodeChunks<ReplyDecoder, Reply>(decoder, chunks, [](const ReplyDecoder& d) {
        FUZZ_CHECK(d.buffered() <= ReplyDecoder::kMaxFrame, QString::number(d.buffered()));
    });
    r.buffered = decoder.buffered();
    r.unframed = decoder.unframedBytes();
    return r;
}

// The canonical frame of a valid reply, without CR.
QByteArray canonical(const Reply& r)
{
    const bool longForm = r.kind == Reply::Kind::Long || r.kind == Reply::Kind::LongUnknown;
    QByteArray out = r.address == 0 ? QByteArray()
                     : longForm     ? QByteArray::number(r.address)
                                    : QByteArray::number(r.address).rightJustified(3, '0');
    switch (r.kind) {
    case Reply::Kind::Echo:
        return out + r.key + (r.value ? QByteArray::number(*r.value) : QByteArray());
    case Reply::Kind::Read:
        if (r.key == "ZE")
            return out + "ZE" +
                   (r.index >= 0 ? QByteArray::number(r.index) + formatSigned(*r.value) : r.text);
        return out + r.key + QByteArray::number(*r.value);
    case Reply::Kind::Record:
        return out + formatRecord(r.recordData);
    case Reply::Kind::Firmware:
        return out + "v " + r.firmware.text.toLatin1();
    case Reply::Kind::Unknown:
        return out + r.key + '?';
    case Reply::Kind::Long:
        return out + r.key +
               (r.assignment ? '=' + QByteArray::number(*r.value) : formatSigned(*r.value));
    case Reply::Kind::LongUnknown:
        return out + ":?";
    case Reply::Kind::HostEcho:
        return r.raw;
    case Reply::Kind::Invalid:
        break;
    }
    return {};
}

void checkReencodes(const Reply& r)
{
    const QByteArray once = canonical(r);
    const Reply again = ReplyDecoder::parse(once);
    FUZZ_CHECK(sameMeaning(again, r), describe(r) + " -> " + describe(again));
    FUZZ_CHECK(canonical(again) == once, fuzz::hex(once) + " is no fixed point");
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const int address = kMinAddress + int(in.next(1) % kMaxAddress);
    const qint64 value = qint64(in.next(5) % 20000000001ull) - 10000000000ll; // 11 digits
    const QByteArray frame = encode::command(address, "s", value);
    CommandDecoder commands;
    const QList<Command> c = commands.feed(frame);
    FUZZ_CHECK(c.size() == 1 && c[0].valid && c[0].address == address &&
                   c[0].body == "s" + QByteArray::number(value),
               fuzz::hex(frame));

    RecordData record;
    record.record = int(in.next(1) % (kRecordCount + 1));
    for (char field : recordFieldOrder()) {
        if (in.next(1) & 1)
            record.fields << qMakePair(field, qint64(in.next(4) % 2000001) - 1000000);
    }
    if (record.fields.size() < 2)
        return; // one field is a plain read, not a record string
    const QByteArray text =
        QByteArray::number(address).rightJustified(3, '0') + formatRecord(record);
    const Reply r = ReplyDecoder::parse(text);
    FUZZ_CHECK(r.kind == Reply::Kind::Record && r.address == address && r.record == record.record &&
                   r.recordData.fields == record.fields,
               describe(r));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    const Run whole = run({in});
    for (const Run& other : {run(fuzz::split(in)), run(fuzz::bytes(in))}) {
        FUZZ_CHECK(fuzz::sameLists(other.replies, whole.replies, same),
                   "split decodes differently: " + describeAll(whole.replies).join('|'));
        FUZZ_CHECK(other.buffered == whole.buffered && other.unframed == whole.unframed,
                   "split leaves other state");
    }
    qsizetype accounted = whole.buffered + whole.unframed;
    for (const Reply& r : whole.replies) {
        accounted += r.raw.size();
        FUZZ_CHECK(!r.raw.isEmpty() && r.raw.size() <= ReplyDecoder::kMaxFrame + 1, describe(r));
        FUZZ_CHECK((r.kind == Reply::Kind::Invalid) == !r.error.isEmpty(), describe(r));
        if (r.kind == Reply::Kind::Invalid)
            continue;
        for (const auto& f : r.recordData.fields)
            FUZZ_CHECK(recordFieldOrder().contains(f.first), describe(r));
        checkReencodes(r);
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
