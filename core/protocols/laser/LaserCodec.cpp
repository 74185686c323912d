#include "LaserCodec.h"
#include <QCoreApplication>

namespace stepdeck::laser {

LineSettings lineSettings()
{
    LineSettings line;
    line.baudRate = 9600;
    line.dataBits = 8;
    line.stopBits = 1;
    line.parity = LineSettings::Parity::None;
    return line;
}

namespace {
constexpr char kLf = '\n';

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// Five ASCII digits at body[from..from+4] as a number; the caller has checked they are digits.
int fiveDigits(const QByteArray& body, int from)
{
    int value = 0;
    for (int i = from; i < from + 5; ++i)
        value = value * 10 + (body.at(i) - '0');
    return value;
}

QByteArray digits(int position)
{
    return QByteArray::number(position).rightJustified(5, '0');
}

// Every character a digit, exactly seven of them: both frame kinds are seven ASCII digits.
DecodeError checkDigits(const QByteArray& body)
{
    if (body.size() != kBodySize)
        return body.size() > kBodySize ? DecodeError::Overlong : DecodeError::WrongLength;
    for (char c : body) {
        if (!isDigit(c))
            return DecodeError::NotDigit;
    }
    return DecodeError::None;
}

template <typename Frame> Decoded<Frame> failed(const QByteArray& body, DecodeError error)
{
    Decoded<Frame> d;
    d.error = error;
    d.raw = body.left(kFrameSize);
    return d;
}
} // namespace

std::optional<Axis> axisFromNumber(int number)
{
    switch (number) {
    case 1:
        return Axis::X;
    case 2:
        return Axis::Y;
    case 3:
        return Axis::Z;
    default:
        return std::nullopt;
    }
}

int axisNumber(Axis axis)
{
    // Axis numbers 1..3 for the first three axes ("up to 3 motoraxis"); 0: none.
    return axis.index() < 3 ? axis.index() + 1 : 0;
}

bool isValidPosition(qint64 position)
{
    return position >= 0 && position <= kMaxPosition;
}

QByteArray encodeCommand(const CommandFrame& frame)
{
    const int axis = axisNumber(frame.axis);
    const int position = frame.command == Command::Home ? 0 : frame.position;
    if (axis == 0 || !isValidPosition(position))
        return {};
    return QByteArray::number(int(frame.command)) + QByteArray::number(axis) + digits(position) +
           kCr;
}

QByteArray encodeHome(Axis axis)
{
    return encodeCommand({Command::Home, axis, 0});
}

QByteArray encodeMove(Axis axis, int position)
{
    return encodeCommand({Command::Move, axis, position});
}

QByteArray encodeStatus(const StatusFrame& frame)
{
    const int axis = axisNumber(frame.axis);
    if (axis == 0 || !isValidPosition(frame.position))
        return {};
    return QByteArray::number(axis) + digits(frame.position) +
           QByteArray::number(int(frame.status)) + kCr;
}

QString describeError(DecodeError error)
{
    switch (error) {
    case DecodeError::None:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec", "no error");
    case DecodeError::WrongLength:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "wrong length (a frame is 7 digits and CR)");
    case DecodeError::Overlong:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "too long (more than 7 characters before the CR)");
    case DecodeError::NotDigit:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "a character that is not a digit");
    case DecodeError::UnknownAxis:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "unknown axis (only 1, 2 and 3 exist)");
    case DecodeError::UnknownCommand:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "unknown command (only 1 home and 2 move)");
    case DecodeError::UnknownStatus:
        return QCoreApplication::translate("stepdeck::laser::LaserCodec",
                                           "unknown status (only 0 to 4)");
    }
    return {};
}

DecodedCommand parseCommand(const QByteArray& body)
{
    if (const DecodeError e = checkDigits(body); e != DecodeError::None)
        return failed<CommandFrame>(body, e);
    const int command = body.at(0) - '0';
    if (command != int(Command::Home) && command != int(Command::Move))
        return failed<CommandFrame>(body, DecodeError::UnknownCommand);
    const std::optional<Axis> axis = axisFromNumber(body.at(1) - '0');
    if (!axis)
        return failed<CommandFrame>(body, DecodeError::UnknownAxis);
    DecodedCommand d;
    d.frame = CommandFrame{Command(command), *axis, fiveDigits(body, 2)};
    d.raw = body;
    return d;
}

DecodedStatus parseStatus(const QByteArray& body)
{
    if (const DecodeError e = checkDigits(body); e != DecodeError::None)
        return failed<StatusFrame>(body, e);
    const std::optional<Axis> axis = axisFromNumber(body.at(0) - '0');
    if (!axis)
        return failed<StatusFrame>(body, DecodeError::UnknownAxis);
    const int status = body.at(6) - '0';
    if (status > int(Status::DoorClosed))
        return failed<StatusFrame>(body, DecodeError::UnknownStatus);
    DecodedStatus d;
    d.frame = StatusFrame{*axis, fiveDigits(body, 1), Status(status)};
    d.raw = body;
    return d;
}

QList<FrameSplitter::Piece> FrameSplitter::feed(const QByteArray& bytes)
{
    QList<Piece> out;
    for (char c : bytes) {
        if (c == kCr) {
            if (m_discarding) {
                ++m_dropped;
            } else {
                out << Piece{m_buffer, m_buffer.size() == kBodySize ? DecodeError::None
                                                                    : DecodeError::WrongLength};
            }
            m_buffer.clear();
            m_discarding = false;
            m_afterCr = true;
            continue;
        }
        const bool skipLf = c == kLf && m_afterCr;
        m_afterCr = false;
        if (skipLf || m_discarding) {
            ++m_dropped;
            continue;
        }
        if (m_buffer.size() == kBodySize) {
            // An eighth character: report once, then drop everything up to the next CR.
            out << Piece{m_buffer + c, DecodeError::Overlong};
            m_buffer.clear();
            m_discarding = true;
            continue;
        }
        m_buffer += c;
    }
    return out;
}

void FrameSplitter::reset()
{
    m_dropped = 0;
    m_buffer.clear();
    m_discarding = false;
    m_afterCr = false;
}

QList<DecodedCommand> CommandDecoder::feed(const QByteArray& bytes)
{
    QList<DecodedCommand> out;
    for (const FrameSplitter::Piece& piece : m_splitter.feed(bytes)) {
        out << (piece.error == DecodeError::None ? parseCommand(piece.body)
                                                 : failed<CommandFrame>(piece.body, piece.error));
    }
    return out;
}

QList<DecodedStatus> StatusDecoder::feed(const QByteArray& bytes)
{
    QList<DecodedStatus> out;
    for (const FrameSplitter::Piece& piece : m_splitter.feed(bytes)) {
        out << (piece.error == DecodeError::None ? parseStatus(piece.body)
                                                 : failed<StatusFrame>(piece.body, piece.error));
    }
    return out;
}

QString commandText(const CommandFrame& frame)
{
    if (frame.command == Command::Home)
        return QCoreApplication::translate("stepdeck::laser::LaserCodec", "home %1")
            .arg(axisName(frame.axis));
    return QCoreApplication::translate("stepdeck::laser::LaserCodec", "move %1 to %2")
        .arg(axisName(frame.axis))
        .arg(frame.position);
}

QString statusText(const StatusFrame& frame)
{
    QString what;
    switch (frame.status) {
    case Status::TargetReached:
        what = QCoreApplication::translate("stepdeck::laser::LaserCodec", "target reached");
        break;
    case Status::EndSwitch:
        what = QCoreApplication::translate("stepdeck::laser::LaserCodec", "end switch");
        break;
    case Status::HomeSwitch:
        what = QCoreApplication::translate("stepdeck::laser::LaserCodec", "home switch");
        break;
    case Status::DoorOpened:
        what = QCoreApplication::translate("stepdeck::laser::LaserCodec", "door opened");
        break;
    case Status::DoorClosed:
        what = QCoreApplication::translate("stepdeck::laser::LaserCodec", "door closed");
        break;
    }
    return QCoreApplication::translate("stepdeck::laser::LaserCodec", "%1 at %2: %3")
        .arg(axisName(frame.axis))
        .arg(frame.position)
        .arg(what);
}

} // namespace stepdeck::laser
