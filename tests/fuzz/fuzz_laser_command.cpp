// libFuzzer target: the laser -> axis command decoder (axis side: simulator, laser bridge).
// Invariants: see LaserFuzz.h.
#include "LaserFuzz.h"

using namespace stepdeck::laser;

namespace {
void reencode(const CommandFrame& f, const QByteArray& raw)
{
    const QByteArray once = encodeCommand(f);
    const QByteArray expected = f.command == Command::Home ? raw.left(2) + "00000\r" : raw + '\r';
    FUZZ_CHECK(once == expected, fuzz::hex(raw) + " -> " + fuzz::hex(once));
    const DecodedCommand again = parseCommand(once.chopped(1));
    FUZZ_CHECK(again.ok() && again.frame->command == f.command && again.frame->axis == f.axis &&
                   (f.command == Command::Home || again.frame->position == f.position),
               fuzz::hex(once));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    const auto axis = axisFromNumber(1 + int(in.next(1) % kAxisCount));
    const int position = int(in.next(3) % (kMaxPosition + 1));
    for (const QByteArray& frame : {encodeMove(*axis, position), encodeHome(*axis)}) {
        CommandDecoder decoder;
        const QList<DecodedCommand> d = decoder.feed(frame);
        FUZZ_CHECK(d.size() == 1 && d[0].ok() && d[0].frame->axis == *axis, fuzz::hex(frame));
        FUZZ_CHECK(d[0].frame->position == (d[0].frame->command == Command::Move ? position : 0),
                   fuzz::hex(frame));
    }
    // Out of range or an axis the protocol lacks: the encoder refuses (empty), never a frame.
    const int bad = kMaxPosition + 1 + int(in.next(2));
    FUZZ_CHECK(encodeMove(*axis, bad).isEmpty() &&
                   encodeMove(*axis, -1 - int(in.next(2))).isEmpty() &&
                   encodeMove(stepdeck::Axis::U, position).isEmpty(),
               QString::number(bad));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    fuzz::laser::check<CommandDecoder, CommandFrame>(in, reencode);
    for (const DecodedCommand& d : CommandDecoder().feed(in)) {
        if (d.ok())
            FUZZ_CHECK(!commandText(*d.frame).isEmpty(), fuzz::hex(d.raw));
        FUZZ_CHECK(!describeError(d.error).isEmpty(), fuzz::hex(d.raw));
    }
    checkEncoders(in);
    return 0;
}
