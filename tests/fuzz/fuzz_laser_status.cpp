// libFuzzer target: the axis -> laser status decoder (laser side: the laser-axis adapter).
// Invariants: see LaserFuzz.h.
#include "LaserFuzz.h"

using namespace stepdeck::laser;

namespace {
void reencode(const StatusFrame& f, const QByteArray& raw)
{
    const QByteArray once = encodeStatus(f);
    FUZZ_CHECK(once == raw + '\r', fuzz::hex(raw) + " -> " + fuzz::hex(once));
    const DecodedStatus again = parseStatus(once.chopped(1));
    FUZZ_CHECK(again.ok() && *again.frame == f, fuzz::hex(once));
}

void checkEncoders(const QByteArray& data)
{
    fuzz::Reader in(data);
    StatusFrame f;
    f.axis = *axisFromNumber(1 + int(in.next(1) % kAxisCount));
    f.position = int(in.next(3) % (kMaxPosition + 1));
    f.status = Status(in.next(1) % (int(Status::DoorClosed) + 1));
    const QByteArray frame = encodeStatus(f);
    StatusDecoder decoder;
    const QList<DecodedStatus> d = decoder.feed(frame);
    FUZZ_CHECK(d.size() == 1 && d[0].ok() && *d[0].frame == f, fuzz::hex(frame));
    f.position = kMaxPosition + 1 + int(in.next(2));
    FUZZ_CHECK(encodeStatus(f).isEmpty(), QString::number(f.position));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QByteArray in = fuzz::input(data, size);
    fuzz::laser::check<StatusDecoder, StatusFrame>(in, reencode);
    for (const DecodedStatus& d : StatusDecoder().feed(in)) {
        if (d.ok())
            FUZZ_CHECK(!statusText(*d.frame).isEmpty(), fuzz::hex(d.raw));
    }
    checkEncoders(in);
    return 0;
}
