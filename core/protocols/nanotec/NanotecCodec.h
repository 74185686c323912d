#pragma once
#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QPair>
#include <QString>
#include <optional>

// Nanotec SMCI33 / SMCI47-S ASCII protocol (manual:
// nanotec-smci33-smci47s-command-reference.de.txt). Pure and streaming: no I/O, no timers,
// bounded buffers.
namespace stepdeck::nanotec {

// The translation context of the codec's texts (decode errors, status bit descriptions).
class Codec
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::nanotec::Codec)
};

// Section 1.1: addresses 1..254; '*' addresses every drive on the bus. 0 and 255 are reserved
// for EEPROM failures (5.4), so they never name a drive here.
constexpr int kBroadcast = -1;
constexpr int kMinAddress = 1;
constexpr int kMaxAddress = 254;
constexpr int kRecordCount = 32; // section 4: records 1..32 in EEPROM
constexpr int kErrorSlots = 32;  // 5.15: 32 error memory slots

bool isValidAddress(int address);

// ---- host -> drive (section 1.1 / 1.2) ----
namespace encode {
// "#<addr><cmd>\r", e.g. "#1A\r". Returns an empty array for commands this program never
// sends: '|0' (the drive stops answering, 6.4) and '@A' (bootloader, 5.32).
QByteArray command(int address, const QByteArray& cmd);
// "#<addr><cmd><value>\r", e.g. "#1s1000\r", "#1s-50\r" (positive values without '+').
QByteArray command(int address, const QByteArray& cmd, qint64 value);
// "#<addr>Z<cmd>\r" (section 3) or "#<addr>Z<record><cmd>\r" (5.19) for a record's value.
QByteArray read(int address, const QByteArray& cmd, int record = 0);
QByteArray readRecord(int address, int record = 0);          // "#1Z|\r", "#1Z5|\r" (6.4)
QByteArray readErrorMemory(int address, int index);          // "#1ZE5\r" (5.15)
QByteArray longRead(int address, const QByteArray& keyword); // "#1:CL_motor_pp\r"
QByteArray longWrite(int address, const QByteArray& keyword, qint64 value); // "...=100\r"
} // namespace encode

// Why the host must not send these frames; empty when the body is allowed.
QString forbiddenReason(const QByteArray& body);

// The part of a command body that a reply echoes back and the host matches on:
// "s1000" -> "s", "Zs" -> "Zs", "Z5s" -> "Z5s", "ZE5" -> "ZE", "Z5|" -> "Z5|",
// ":CL_motor_pp=100" -> ":CL_motor_pp", "v" -> "v".
QByteArray commandKey(const QByteArray& body);

// Signed decimal with optional sign and at most 11 digits ("+50", "-3", "1000"); false for
// anything else.
bool parseNumber(const QByteArray& text, qint64* value);
QByteArray formatSigned(qint64 value); // always with sign: "+50", "-3" (record strings)

// 5.22: "v PD4_RS485_26-09-2007" -> hardware PD4, interface RS485, date 26-09-2007.
struct FirmwareInfo
{
    QString hardware;
    QString interface;
    QString date;
    QString text; // the whole string after "v "
};
std::optional<FirmwareInfo> parseFirmware(const QByteArray& text);

// 6.4: "p+1s+1u+400o+860n+1000b+55800d+1t+0W+1P+0N+0" (the '|' is not sent back).
struct RecordData
{
    int record = 0; // 0: the record loaded in RAM
    QList<QPair<char, qint64>> fields;
    std::optional<qint64> value(char cmd) const;
};
// The record fields in the manual's order (section 4).
const QByteArray& recordFieldOrder();            // "psuonbdtWPN"
QByteArray formatRecord(const RecordData& data); // without address and terminator

// 5.21 status byte.
struct DriveState
{
    bool ready = false;            // bit 0
    bool zeroReached = false;      // bit 1
    bool positionError = false;    // bit 2
    bool input1WhileReady = false; // bit 3
    int mode = 0;                  // bits 4..6, see motorModeName()
};
DriveState decodeStatus(qint64 word);
quint8 encodeStatus(const DriveState& state);
QString motorModeName(int mode);     // 5.5 / 5.21: "positioning", "speed", ...
QString describeStatus(qint64 word); // "ready, zero position reached, mode positioning"

// 5.15 error codes.
namespace error {
constexpr int LowVoltage = 0x01;
constexpr int Temperature = 0x02;
constexpr int Driver = 0x04; // TMC: the driver chip reported an error
constexpr int Eeprom = 0x08;
constexpr int Position = 0x10; // QEI
constexpr int Internal = 0x20;
} // namespace error
QString errorCodeName(int code);        // "ERROR_TEMP" style manual name, or "none"
QString errorCodeDescription(int code); // plain words

// ---- drive -> host ----
struct Reply
{
    enum class Kind {
        Echo,        // "001s1000": a command (with its value) echoed, or a value such as "$17"
        Read,        // "001Zs1000", "001Z5s2000", "001ZE5+8"
        Record,      // "001Zp+1s+1...": Z| / Z<n>|
        Firmware,    // "001v PD4_RS485_26-09-2007"
        Unknown,     // "001/?": the drive does not know the command
        Long,        // "1:CL_motor_pp+50" (read) or "1:CL_motor_pp=100" (write echo)
        LongUnknown, // "1:?"
        HostEcho,    // "#1A": our own frame echoed by a half-duplex adapter
        Invalid,     // garbage or malformed: raw holds the dropped bytes
    };
    Kind kind = Kind::Invalid;
    int address = 0; // 0: the reply carried no address (manual example "Z|")
    QByteArray key;  // see commandKey(); for Unknown the unknown command's key
    std::optional<qint64> value;
    QByteArray text;         // Echo/Read: the text after the command (value as sent)
    int record = 0;          // Read/Record: record number, 0 = RAM
    int index = -1;          // Read "ZE<n>": error slot, -1 when ambiguous
    bool assignment = false; // Long: "=" echo of a write
    RecordData recordData;
    FirmwareInfo firmware;
    QByteArray raw; // the frame without the terminating CR
    QString error;  // Invalid: why
};

// Replies end with CR (1.1). The decoder needs no knowledge of the request; garbage is
// reported as Invalid and decoding resynchronises at the next CR. Never holds more than
// kMaxFrame bytes.
class ReplyDecoder
{
public:
    static constexpr int kMaxFrame = 96;
    QList<Reply> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_buffer.size()); }
    // Bytes consumed that no reply's raw carries: the CR terminators, line feeds and idle
    // zeros between frames, the dropped tail of an overlong frame. Every byte fed is in a
    // raw, in buffered() or counted here.
    qint64 unframedBytes() const { return m_unframed; }
    static Reply parse(const QByteArray& frame); // one frame without CR

private:
    QByteArray m_buffer;
    bool m_discarding = false; // an overlong frame: drop until the next CR
    qint64 m_unframed = 0;
};

// ---- host -> drive, decoded on the device side (simulator, console) ----
struct Command
{
    bool broadcast = false;
    int address = 0;
    QByteArray body; // everything between the address and CR
    bool valid = true;
    QString error;
    QByteArray raw;
};

// Frames start with '#' and end with CR (1.1): bytes before '#' are garbage, a '#' inside a
// frame starts a new one. Bounded like the reply decoder.
class CommandDecoder
{
public:
    static constexpr int kMaxFrame = 96;
    QList<Command> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_buffer.size()); }
    // Bytes consumed that no command's raw carries: bytes before a '#' and the dropped tail of
    // an overlong frame. Every byte fed is in a raw, in buffered() or counted here.
    qint64 unframedBytes() const { return m_unframed; }

private:
    QByteArray m_buffer;
    bool m_inFrame = false;
    qint64 m_unframed = 0;
};

} // namespace stepdeck::nanotec
