// libFuzzer target: the EMIS SMC-IC4 command side (EmisGrammar.h): the device-side framing
// (simulator, traffic console) and the command grammar that also validates input programs
// (9.17, `program` in the CLI and the program editor). Invariants: one chunk, any split and
// byte by byte frame alike; every byte is in a frame's text, its terminator, buffered or
// skipped (blanks between commands, empty lines, overlong tails); the buffer stays within one
// frame; every valid command re-encodes through the host's encoders (encode::, canonical form:
// no '+', no leading zeros, axes in X,Y,Z,U order for $H) to a command of the same meaning
// whose encoding is a fixed point; validation never crashes and agrees with its parts; every
// encoder's output frames and parses to the values it was given.
#include "FuzzSupport.h"
#include "protocols/emis/EmisGrammar.h"

using namespace stepdeck;
using namespace stepdeck::emis;

namespace {
using K = Command::Kind;

bool sameEntry(const SystemEntry& a, const SystemEntry& b)
{
    return a.key == b.key && a.values == b.values && a.idle == b.idle &&
           a.normallyClosed == b.normallyClosed && a.ramp == b.ramp && a.flexStart == b.flexStart &&
           a.flexWork == b.flexWork && a.flexRamp == b.flexRamp;
}

bool sameTargets(const QList<VectorTarget>& a, const QList<VectorTarget>& b)
{
    return fuzz::sameLists(a, b, [](const VectorTarget& x, const VectorTarget& y) {
        return x.axis == y.axis && x.value == y.value && x.absolute == y.absolute;
    });
}

// What a command means (not how it was written): the $H axes as a set (the encoder orders them).
bool sameMeaning(const Command& a, const Command& b)
{
    QList<Axis> axesA = a.axes, axesB = b.axes;
    std::sort(axesA.begin(), axesA.end());
    std::sort(axesB.begin(), axesB.end());
    return a.kind == b.kind && a.number == b.number && a.on == b.on && a.axis == b.axis &&
           a.value == b.value && a.idle == b.idle && axesA == axesB &&
           a.simultaneous == b.simultaneous && sameTargets(a.targets, b.targets) &&
           sameEntry(a.system, b.system) && a.title == b.title;
}

QString describe(const Command& c)
{
    return QStringLiteral("%1 '%2' %3").arg(int(c.kind)).arg(fuzz::hex(c.text), c.error);
}

// The host encoder's bytes for a parsed command, terminator included.
QByteArray canonical(const Command& c)
{
    switch (c.kind) {
    case K::Version:
        return encode::version();
    case K::Input:
        return encode::input(c.number);
    case K::AllInputs:
        return encode::allInputs();
    case K::Output:
        return encode::output(c.number, c.on);
    case K::StartSpeed:
        return c.axis ? encode::startSpeed(*c.axis, c.value) : encode::startSpeedAll(c.value);
    case K::WorkSpeed:
        return c.axis ? encode::workSpeed(*c.axis, c.value) : encode::workSpeedAll(c.value);
    case K::ReferenceSpeed:
        return encode::referenceSpeed(c.value);
    case K::Ramp:
        return encode::ramp(c.value);
    case K::StepResolution:
        return encode::stepResolution(*c.axis, c.value);
    case K::Current:
        return encode::current(*c.axis, c.value, c.idle);
    case K::Home:
        return encode::home(c.axes, c.simultaneous);
    case K::ReferenceOffset:
        return encode::referenceOffset(*c.axis, c.value);
    case K::Vector:
        return encode::vector(c.targets);
    case K::Interpolation:
        return encode::interpolation(c.on);
    case K::Wait:
        return encode::wait(c.value);
    case K::SystemWrite:
        return "##" + formatSystemEntry(c.system) + kCr;
    case K::ReadSystem:
        return encode::readSystem();
    case K::ClearSystem:
        return encode::clearSystem();
    case K::ProgramOpen:
        return encode::programOpen(c.number);
    case K::ProgramHeader:
        return encode::programHeader(c.number, c.title);
    case K::ProgramEnd:
        return encode::programEnd();
    case K::ProgramErase:
        return encode::programErase(c.number);
    case K::Invalid:
        break;
    }
    return {};
}

// Encoder bytes -> the one frame they make -> the parsed command.
Command reparse(const QByteArray& bytes)
{
    CommandDecoder decoder;
    const QList<CommandDecoder::Frame> frames = decoder.feed(bytes);
    FUZZ_CHECK(frames.size() == 1 && !frames[0].overlong && decoder.buffered() == 0,
               fuzz::hex(bytes));
    return parseCommand(frames[0].text, frames[0].terminator);
}

void checkCommand(const CommandDecoder::Frame& f)
{
    const Command c = parseCommand(f.text, f.terminator);
    FUZZ_CHECK((c.kind == K::Invalid) == !c.error.isEmpty(), describe(c));
    const QString range = c.kind == K::Invalid ? QString() : rangeError(c);
    const QString refusal = programRefusal(c);
    if (f.terminator == kCr) {
        const QString verdict = validateProgramLine(f.text);
        FUZZ_CHECK(verdict.isEmpty() ==
                       (c.kind != K::Invalid && refusal.isEmpty() && range.isEmpty()),
                   describe(c) + " / " + verdict);
    }
    if (c.kind == K::Invalid)
        return;
    const QByteArray once = canonical(c);
    const Command again = reparse(once);
    FUZZ_CHECK(sameMeaning(again, c), describe(c) + " -> " + describe(again));
    FUZZ_CHECK(canonical(again) == once, fuzz::hex(once) + " is no fixed point");
    FUZZ_CHECK(rangeError(again).isEmpty() == range.isEmpty(), describe(c));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const Axis axis = letterAxes()[int(in.next(1) % 4)];
    QList<VectorTarget> targets;
    for (Axis a : letterAxes()) {
        if (in.next(1) & 1) {
            const qint64 v = qint64(in.next(4) % 4294967295ull) - 2147483647ll;
            targets << VectorTarget{a, v, bool(in.next(1) & 1)};
        }
    }
    if (!targets.isEmpty()) {
        const Command v = reparse(encode::vector(targets));
        FUZZ_CHECK(v.kind == K::Vector && sameTargets(v.targets, targets) &&
                       rangeError(v).isEmpty(),
                   describe(v));
    }
    const qint64 speed = limits::kSpeedMin + qint64(in.next(2) % limits::kSpeedMax);
    const Command s = reparse(encode::workSpeed(axis, speed));
    FUZZ_CHECK(s.kind == K::WorkSpeed && s.axis == axis && s.value == speed &&
                   validateProgramLine(s.text).isEmpty(),
               describe(s));
    const qint64 run = qint64(in.next(1) % (limits::kRunCurrentMax + 1));
    const qint64 idle = qint64(in.next(1) % (limits::kIdleCurrentMax + 1));
    const Command cur = reparse(encode::current(axis, run, idle));
    FUZZ_CHECK(cur.kind == K::Current && cur.axis == axis && cur.value == run && cur.idle == idle,
               describe(cur));
    const int number = 1 + int(in.next(1) % kOutputCount);
    const Command out = reparse(encode::output(number, in.next(1) & 1));
    FUZZ_CHECK(out.kind == K::Output && out.number == number && rangeError(out).isEmpty(),
               describe(out));
    QByteArray title = data.left(limits::kTitleMax);
    for (char& ch : title) {
        const auto b = static_cast<unsigned char>(ch);
        ch = char(0x20 + b % 0x5F); // printable ASCII, the only thing a header holds
    }
    const Command h = reparse(encode::programHeader(number, title));
    FUZZ_CHECK(h.kind == K::ProgramHeader && h.number == number && h.title == title, describe(h));
}
} // namespace

namespace {
struct Run
{
    QList<CommandDecoder::Frame> frames;
    int buffered = 0;
    qint64 skipped = 0;
};

Run run(const QList<QByteArray>& chunks)
{
    CommandDecoder decoder;
    Run r;
    r.frames = fuzz::decodeChunks<CommandDecoder, CommandDecoder::Frame>(
        decoder, chunks, [](const CommandDecoder& d) {
            FUZZ_CHECK(d.buffered() <= CommandDecoder::kMaxFrame, QString::number(d.buffered()));
        });
    r.buffered = decoder.buffered();
    r.skipped = decoder.skippedBytes();
    return r;
}

bool sameFrame(const CommandDecoder::Frame& a, const CommandDecoder::Frame& b)
{
    return a.text == b.text && a.terminator == b.terminator && a.overlong == b.overlong;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    const Run whole = run({in});
    for (const Run& other : {run(fuzz::split(in)), run(fuzz::bytes(in))}) {
        FUZZ_CHECK(fuzz::sameLists(other.frames, whole.frames, sameFrame),
                   "split frames differently");
        FUZZ_CHECK(other.buffered == whole.buffered && other.skipped == whole.skipped,
                   "split leaves other state");
    }
    qsizetype accounted = whole.buffered + whole.skipped;
    for (const CommandDecoder::Frame& f : whole.frames) {
        accounted += f.text.size() + 1;
        FUZZ_CHECK(f.text.size() <= CommandDecoder::kMaxFrame && (!f.overlong || f.text.isEmpty()),
                   fuzz::hex(f.text));
        if (!f.overlong)
            checkCommand(f);
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
    checkEncoders(in);
    return 0;
}
