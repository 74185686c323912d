// libFuzzer target: the EMIS SMC-IC4 reply decoder (host side, EmisCodec.h) and the answer
// parsers behind it (version, inputs, *PRSYS). Invariants: one chunk, any split and byte by
// byte decode alike; every byte is in an event's text or raw, is its terminator, is buffered
// or skipped (blanks around a text, an overlong tail); the buffer stays within kMaxText;
// every valid event re-encodes (text + terminator, <DCn>) to an event of its own; the
// *PRSYS list re-formats (formatSystemParameters) to a list of the same entries that is a
// fixed point; the input answers built from levels parse back to those levels.
#include "FuzzSupport.h"
#include "protocols/emis/EmisGrammar.h"

using namespace stepdeck;
using namespace stepdeck::emis;

namespace {
using Kind = Event::Kind;

bool same(const Event& a, const Event& b)
{
    return a.kind == b.kind && a.text == b.text && a.axis == b.axis && a.raw == b.raw &&
           a.error == b.error;
}

QString describe(const Event& e)
{
    return QStringLiteral("%1 '%2' %3 [%4] %5")
        .arg(int(e.kind))
        .arg(fuzz::hex(e.text))
        .arg(e.axis.index())
        .arg(fuzz::hex(e.raw), e.error);
}

struct Run
{
    QList<Event> events;
    int buffered = 0;
    qint64 skipped = 0;
};

Run run(const QList<QByteArray>& chunks)
{
    ReplyDecoder decoder;
    Run r;
    r.events = fuzz::decodeChunks<ReplyDecoder, Event>(decoder, chunks, [](const ReplyDecoder& d) {
        FUZZ_CHECK(d.buffered() <= ReplyDecoder::kMaxText, QString::number(d.buffered()));
    });
    r.buffered = decoder.buffered();
    r.skipped = decoder.skippedBytes();
    return r;
}

char terminator(Kind kind)
{
    return kind == Kind::Ack ? kAck : (kind == Kind::Nak ? kNak : kBel);
}

bool sameEntries(const QList<SystemEntry>& a, const QList<SystemEntry>& b)
{
    return fuzz::sameLists(a, b, [](const SystemEntry& x, const SystemEntry& y) {
        return x.key == y.key && x.values == y.values && x.idle == y.idle &&
               x.normallyClosed == y.normallyClosed && x.ramp == y.ramp &&
               x.flexStart == y.flexStart && x.flexWork == y.flexWork && x.flexRamp == y.flexRamp;
    });
}

void checkAnswer(const QByteArray& text)
{
    parseVersion(text);
    isReady(text);
    for (int n = 1; n <= kInputCount; ++n)
        parseInput(text, n);
    if (const auto levels = parseAllInputs(text)) {
        QByteArray bits;
        for (bool on : *levels)
            bits += on ? '1' : '0';
        FUZZ_CHECK(parseAllInputs("@IG " + bits) == levels, fuzz::hex(text));
    }
    const SystemParameters p = parseSystemParameters(text);
    if (p.entries.isEmpty())
        return;
    const QByteArray once = formatSystemParameters(p.entries);
    const SystemParameters again = parseSystemParameters(once);
    FUZZ_CHECK(sameEntries(again.entries, p.entries) && again.unparsed.isEmpty(), fuzz::hex(once));
    FUZZ_CHECK(formatSystemParameters(again.entries) == once, fuzz::hex(once) + " no fixed point");
}

void reencode(const Event& e)
{
    QByteArray once;
    if (e.kind == Kind::Arrived)
        once = QByteArray(1, arrivalCode(e.axis));
    else
        once = e.text + terminator(e.kind);
    ReplyDecoder decoder;
    const QList<Event> again = decoder.feed(once);
    FUZZ_CHECK(again.size() == 1 && same(again[0], e) && decoder.buffered() == 0 &&
                   decoder.skippedBytes() == 0,
               describe(e) + " -> " + fuzz::hex(once));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const int number = 1 + int(in.next(1) % kInputCount);
    const bool level = in.next(1) & 1;
    const QByteArray answer = "@I" + QByteArray::number(number) + ' ' + (level ? '1' : '0');
    FUZZ_CHECK(parseInput(answer, number) == level, answer);
    SystemEntry ramp;
    ramp.key = SystemEntry::Key::Ramp;
    ramp.ramp = qint64(in.next(2));
    SystemEntry speeds;
    speeds.key = SystemEntry::Key::WorkSpeed;
    for (Axis a : letterAxes()) {
        if (in.next(1) & 1)
            speeds.values.insert(a, qint64(in.next(2)));
    }
    QList<SystemEntry> entries{ramp};
    if (!speeds.values.isEmpty())
        entries << speeds;
    const SystemParameters p = parseSystemParameters(formatSystemParameters(entries));
    FUZZ_CHECK(sameEntries(p.entries, entries), fuzz::hex(formatSystemParameters(entries)));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    const Run whole = run({in});
    for (const Run& other : {run(fuzz::split(in)), run(fuzz::bytes(in))}) {
        FUZZ_CHECK(fuzz::sameLists(other.events, whole.events, same), "split decodes differently");
        FUZZ_CHECK(other.buffered == whole.buffered && other.skipped == whole.skipped,
                   "split leaves other state");
    }
    qsizetype accounted = whole.buffered + whole.skipped;
    for (const Event& e : whole.events) {
        FUZZ_CHECK((e.kind == Kind::Invalid) == !e.error.isEmpty(), describe(e));
        FUZZ_CHECK(e.text.size() <= ReplyDecoder::kMaxText &&
                       e.raw.size() <= ReplyDecoder::kMaxText + 1,
                   describe(e));
        if (e.kind == Kind::Invalid) {
            FUZZ_CHECK(!e.raw.isEmpty() && e.text.isEmpty(), describe(e));
            accounted += e.raw.size();
            continue;
        }
        accounted += 1 + e.text.size();
        reencode(e);
        if (e.kind == Kind::Ack)
            checkAnswer(e.text);
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
