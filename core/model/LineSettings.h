#pragma once
#include <QtGlobal>

namespace stepdeck {

// Serial line settings; each model declares its own (E-LAB: 57600 8N2, no flow control).
struct LineSettings
{
    qint32 baudRate = 9600;
    int dataBits = 8;
    int stopBits = 1; // 1 or 2
    enum class Parity { None, Even, Odd } parity = Parity::None;

    // Bits on the wire per character (start + data + parity + stop) for pacing estimates.
    int bitsPerCharacter() const
    {
        return 1 + dataBits + (parity == Parity::None ? 0 : 1) + stopBits;
    }
    // Microseconds one character occupies on the wire.
    double characterTimeUs() const { return 1e6 * bitsPerCharacter() / double(baudRate); }
};

} // namespace stepdeck
