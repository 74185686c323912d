#pragma once
#include "model/Axis.h"
#include "model/LineSettings.h"
#include <QByteArray>
#include <QList>
#include <QString>
#include <optional>

// The motor-axis protocol of a laser marker (manual: laser-motoraxis-rs232.en.txt). One codec
// for both directions: laser -> axis commands and axis -> laser status responses. Pure and
// streaming: no I/O, no timers, bounded buffers. Shared by the laser-axis adapter (laser side),
// its simulator (axis side), the laser bridge (axis side) and the scripted laser in tests.
namespace stepdeck::laser {

// "|Command-Byte|Axis-Byte|target-position 5-digits|CR| (8-byte frame)" and
// "|Axis-Byte|actual-position 5-digits|Status-Byte|CR| (8-byte frame)".
constexpr int kFrameSize = 8; // seven ASCII digits and CR
constexpr int kBodySize = 7;  // the frame without its CR
constexpr char kCr = '\r';
// "The range of the target-position is thus [0000...99999]". The status section says
// "[0000...9999]" for the actual position; with five digits on the wire we read that as a typo
// and accept 0..99999 in both directions.
constexpr int kMaxPosition = 99999;
constexpr int kAxisCount = 3; // "The firmware can control up to 3 motoraxis"

// "The port settings are fixed to: baudrate 9600, 8 bit, no parity, 1 stop bit". Part of the
// wire protocol, so the laser bridge (which speaks it) needs no more than this codec.
LineSettings lineSettings();

// Command-Byte: ASCII '1' move to home, ASCII '2' move to position.
enum class Command { Home = 1, Move = 2 };
// Status-Byte: '0' target reached, '1' end switch, '2' home switch, '3' door opened,
// '4' door closed.
enum class Status {
    TargetReached = 0,
    EndSwitch = 1,
    HomeSwitch = 2,
    DoorOpened = 3,
    DoorClosed = 4
};

// Axis-Byte: ASCII '1' x-axis, '2' y-axis, '3' z-axis.
std::optional<Axis> axisFromNumber(int number); // 1..3
int axisNumber(Axis axis);                      // X=1, Y=2, Z=3; 0 for any other axis
bool isValidPosition(qint64 position);          // 0..99999

struct CommandFrame
{
    Command command = Command::Move;
    Axis axis = Axis::X;
    int position = 0; // Home: ignored on receipt, sent as 00000 ("should be set to 00000")
    bool operator==(const CommandFrame& o) const
    {
        return command == o.command && axis == o.axis && position == o.position;
    }
};

struct StatusFrame
{
    Axis axis = Axis::X;
    int position = 0;
    Status status = Status::TargetReached;
    bool operator==(const StatusFrame& o) const
    {
        return axis == o.axis && position == o.position && status == o.status;
    }
};

// "1100000\r", "2200150\r". Empty for an axis other than X/Y/Z or a position out of range.
QByteArray encodeCommand(const CommandFrame& frame);
QByteArray encodeHome(Axis axis);
QByteArray encodeMove(Axis axis, int position);
// "2001500\r". Empty for an axis other than X/Y/Z or a position out of range.
QByteArray encodeStatus(const StatusFrame& frame);

enum class DecodeError {
    None,
    WrongLength,    // a CR after fewer than seven characters (or none)
    Overlong,       // more than seven characters without a CR; dropped up to the next CR
    NotDigit,       // a character that is not an ASCII digit
    UnknownAxis,    // axis byte other than '1', '2', '3'
    UnknownCommand, // command byte other than '1', '2'
    UnknownStatus,  // status byte other than '0'..'4'
};
QString describeError(DecodeError error); // plain English, for logs

template <typename Frame> struct Decoded
{
    std::optional<Frame> frame;
    DecodeError error = DecodeError::None;
    QByteArray raw; // the frame without CR (at most kFrameSize bytes of an overlong one)
    bool ok() const { return frame.has_value(); }
};
using DecodedCommand = Decoded<CommandFrame>;
using DecodedStatus = Decoded<StatusFrame>;

// One frame body (without CR) of each direction.
DecodedCommand parseCommand(const QByteArray& body);
DecodedStatus parseStatus(const QByteArray& body);

// Frames by CR. A frame is complete at its CR; anything else than seven characters before it
// is an error, and an overlong run is reported once and dropped up to the next CR, where
// decoding resynchronises. A LF right after a CR is skipped (CR LF line ends of terminal
// programs; the manual only names CR). Holds at most kBodySize bytes.
class FrameSplitter
{
public:
    struct Piece
    {
        QByteArray body;
        DecodeError error = DecodeError::None; // WrongLength or Overlong, else None
    };
    QList<Piece> feed(const QByteArray& bytes);
    void reset();
    int buffered() const { return int(m_buffer.size()); }
    // Bytes consumed without appearing in a piece (body or its CR): a LF after a CR, and the
    // tail and CR of an overlong run (checked by the fuzz targets).
    qint64 droppedBytes() const { return m_dropped; }

private:
    qint64 m_dropped = 0;
    QByteArray m_buffer;
    bool m_discarding = false;
    bool m_afterCr = false;
};

// Axis side: decodes the laser's commands.
class CommandDecoder
{
public:
    QList<DecodedCommand> feed(const QByteArray& bytes);
    void reset() { m_splitter.reset(); }
    int buffered() const { return m_splitter.buffered(); }
    qint64 droppedBytes() const { return m_splitter.droppedBytes(); }

private:
    FrameSplitter m_splitter;
};

// Laser side: decodes the axes' status responses.
class StatusDecoder
{
public:
    QList<DecodedStatus> feed(const QByteArray& bytes);
    void reset() { m_splitter.reset(); }
    int buffered() const { return m_splitter.buffered(); }
    qint64 droppedBytes() const { return m_splitter.droppedBytes(); }

private:
    FrameSplitter m_splitter;
};

QString commandText(const CommandFrame& frame); // "home X", "move Y to 150"
QString statusText(const StatusFrame& frame);   // "Y at 150: target reached"

} // namespace stepdeck::laser
