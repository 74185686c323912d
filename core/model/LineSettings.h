#pragma once
#include <QString>
#include <optional>

namespace stepdeck {

// Serial line settings; each model declares its own (E-LAB: 57600 8N2, no flow control).
struct LineSettings
{
    qint32 baudRate = 9600;
    int dataBits = 8;
    int stopBits = 1; // 1 or 2
    enum class Parity { None, Even, Odd } parity = Parity::None;
    // The modem line some boards use as hardware reset. E-LAB: the manual's text says RTS, its
    // pin table puts the reset on the DE-9 pin that is DTR, so the user chooses (RTS default).
    // The transport holds both lines de-asserted on open.
    enum class ResetLine { Rts, Dtr } resetLine = ResetLine::Rts;

    // Bits on the wire per character (start + data + parity + stop) for pacing estimates.
    int bitsPerCharacter() const
    {
        return 1 + dataBits + (parity == Parity::None ? 0 : 1) + stopBits;
    }
    // Microseconds one character occupies on the wire.
    double characterTimeUs() const { return 1e6 * bitsPerCharacter() / double(baudRate); }
    // "57600 8N2": the baud rate and the character frame, as manuals write it.
    QString text() const;
};

// "rts" / "dtr" (CLI --reset-line, settings); nullopt for anything else.
std::optional<LineSettings::ResetLine> resetLineFromName(const QString& name);
QString resetLineName(LineSettings::ResetLine line);

} // namespace stepdeck
