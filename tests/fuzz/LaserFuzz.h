#pragma once
// Shared by the two laser targets (fuzz_laser_command.cpp, fuzz_laser_status.cpp): both
// directions frame alike (seven ASCII digits and CR, LaserCodec.h), so one checker serves both.
// Invariants: one chunk, any split and byte by byte decode alike; every byte is in a frame's
// raw, its CR, buffered, or dropped (LF after CR, overlong tail); the buffer stays within one
// frame body; every valid frame re-encodes to its own bytes (a home command to its canonical
// "00000" position, the manual: "should be set to 00000"); every encoder's output decodes to
// the values it was given.
#include "FuzzSupport.h"
#include "protocols/laser/LaserCodec.h"

namespace fuzz::laser {

using namespace stepdeck::laser;

template <typename Frame> QString describe(const Decoded<Frame>& d)
{
    return QStringLiteral("[%1] ok=%2 error=%3").arg(hex(d.raw)).arg(d.ok()).arg(int(d.error));
}

template <typename Frame> bool same(const Decoded<Frame>& a, const Decoded<Frame>& b)
{
    return a.frame == b.frame && a.error == b.error && a.raw == b.raw;
}

template <typename Frame> struct Run
{
    QList<Decoded<Frame>> frames;
    int buffered = 0;
    qint64 dropped = 0;
};

template <typename Decoder, typename Frame> Run<Frame> run(const QList<QByteArray>& chunks)
{
    Decoder decoder;
    Run<Frame> r;
    r.frames = decodeChunks<Decoder, Decoded<Frame>>(decoder, chunks, [](const Decoder& d) {
        FUZZ_CHECK(d.buffered() <= kBodySize, QString::number(d.buffered()));
    });
    r.buffered = decoder.buffered();
    r.dropped = decoder.droppedBytes();
    return r;
}

// The decoder-independent invariants; `reencode(frame, raw)` checks the valid frames.
template <typename Decoder, typename Frame, typename Reencode>
void check(const QByteArray& in, Reencode reencode)
{
    const Run<Frame> whole = run<Decoder, Frame>({in});
    for (const Run<Frame>& other :
         {run<Decoder, Frame>(split(in)), run<Decoder, Frame>(bytes(in))}) {
        FUZZ_CHECK(sameLists(other.frames, whole.frames, same<Frame>), "split decodes differently");
        FUZZ_CHECK(other.buffered == whole.buffered && other.dropped == whole.dropped,
                   "split leaves other state");
    }
    qsizetype accounted = whole.buffered + whole.dropped;
    for (const Decoded<Frame>& d : whole.frames) {
        FUZZ_CHECK(d.raw.size() <= kFrameSize, describe(d));
        FUZZ_CHECK(d.ok() == (d.error == DecodeError::None), describe(d));
        // An overlong run is reported with its first eight bytes; its CR is dropped later.
        accounted += d.raw.size() + (d.error == DecodeError::Overlong ? 0 : 1);
        if (d.ok()) {
            FUZZ_CHECK(d.raw.size() == kBodySize, describe(d));
            reencode(*d.frame, d.raw);
        }
    }
    FUZZ_CHECK(accounted == in.size(),
               QStringLiteral("%1 of %2 bytes accounted for").arg(accounted).arg(in.size()));
}

} // namespace fuzz::laser
