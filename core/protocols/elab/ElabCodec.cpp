#include "ElabCodec.h"
#include <QCoreApplication>

namespace stepdeck::elab {

namespace {
// Payload patterns, after the control byte: 'h' is one hex digit, '?' one of S/M/A (the
// ramp selector of <ESC>), anything else a literal separator. The separators ", ; . #" also
// check the telegram (manual: "Aufbau der Befehle und Parameter").
struct Format
{
    const char* pattern;
    bool isSigned;
};

constexpr char kTriple16[] = "hhhh,hhhh;hhhh.";
constexpr char kTriple8[] = "hh,hh;hh.";
constexpr char kTriple32[] = "hhhhhhhh,hhhhhhhh;hhhhhhhh.";

// Host -> controller formats (manual section per command, see ElabCodec.h).
const Format* commandFormat(char code)
{
    static const Format none{"", false};
    static const Format triple16u{kTriple16, false};
    static const Format triple16s{kTriple16, true};
    static const Format triple8{kTriple8, false};
    static const Format triple32{kTriple32, true};
    static const Format pair32{"hhhhhhhh,hhhhhhhh;", true};
    static const Format zOnly{"hhhhhhhh.", true};
    static const Format xOnly{"hhhhhhhh,", true};
    static const Format yOnly{"hhhhhhhh;", true};
    static const Format spindle{"hhhhhhhh#", false};
    static const Format byte{"hh", false};
    static const Format ramp{"?hhhh,hhhh;hhhh.", false};
    switch (code) {
    case ctrl::ETX:
    case ctrl::ENQ:
    case ctrl::ACK:
    case ctrl::BEL:
    case ctrl::HT:
    case ctrl::LF:
    case ctrl::CR:
    case ctrl::XOFF:
    case ctrl::SYN:
    case ctrl::ETB:
    case ctrl::GS:
    case ctrl::RS:
        return &none;
    case ctrl::DC4:
    case ctrl::US:
    case ctrl::CAN:
        return &triple16s;
    case ctrl::FS:
        return &triple16u;
    case ctrl::ESC:
        return &ramp;
    case ctrl::SO:
    case ctrl::DLE:
        return &triple8;
    case ctrl::EOT:
        return &triple32;
    case ctrl::FF:
        return &pair32;
    case ctrl::BS:
    case ctrl::VT:
        return &zOnly;
    case ctrl::EM:
        return &xOnly;
    case ctrl::SUB:
        return &yOnly;
    case ctrl::SOH:
        return &spindle;
    case ctrl::STX:
    case ctrl::SI:
        return &byte;
    default:
        return nullptr; // DC2 is handled separately; XON, NAK, NUL are no commands
    }
}

// Controller -> host reply formats ("Allgemeine Befehle": RequestMachineState etc.).
const char* replyPattern(char code)
{
    switch (code) {
    case ctrl::ENQ:
        return "hhhh#";
    case ctrl::HT:
        return "hh#";
    case ctrl::ETB:
        return "hh#";
    case ctrl::ETX:
        return kTriple32;
    default:
        return nullptr;
    }
}

bool isControl(char c)
{
    return quint8(c) < 0x20;
}

bool isHex(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}

// Does `c` fit position `pos` of `pattern`?
bool fits(const char* pattern, int pos, char c)
{
    const char p = pattern[pos];
    if (p == 'h')
        return isHex(c);
    if (p == '?')
        return c == 'S' || c == 'M' || c == 'A';
    return c == p;
}

// Values of the hex groups of a completed payload, sign-extended where the format is signed.
int parseGroups(const char* pattern, const QByteArray& payload, bool isSigned,
                std::array<qint64, 3>* values)
{
    int count = 0;
    int i = 0;
    const int n = int(qstrlen(pattern));
    while (i < n && count < 3) {
        if (pattern[i] != 'h') {
            ++i;
            continue;
        }
        int start = i;
        while (i < n && pattern[i] == 'h')
            ++i;
        const int digits = i - start;
        quint64 v = payload.mid(start, digits).toULongLong(nullptr, 16);
        if (isSigned) {
            const quint64 signBit = 1ull << (digits * 4 - 1);
            if (v & signBit)
                v |= ~((signBit << 1) - 1);
        }
        (*values)[count++] = qint64(v);
    }
    return count;
}

QByteArray hex(quint64 value, int digits)
{
    return QByteArray::number(value, 16).toUpper().rightJustified(digits, '0').right(digits);
}

template <typename T> QByteArray triple(char code, const Triple<T>& v, int digits)
{
    using U = std::make_unsigned_t<T>;
    QByteArray out(1, code);
    out += hex(U(v[0]), digits) + ',' + hex(U(v[1]), digits) + ';' + hex(U(v[2]), digits) + '.';
    return out;
}

} // namespace

namespace {
constexpr WireAxis kWireAxes[] = {
    {Axis::X, 0, axe::XMove, axe::XJog, machine::LimSwX, machine::RefSwX},
    {Axis::Y, 1, axe::YMove, axe::YJog, machine::LimSwY, machine::RefSwY},
    {Axis::Z, 2, axe::ZMove, axe::ZJog, machine::LimSwZ, machine::RefSwZ},
};
} // namespace

const QList<Axis>& boardAxes()
{
    static const QList<Axis> list = [] {
        QList<Axis> out;
        for (const WireAxis& w : kWireAxes)
            out << w.axis;
        return out;
    }();
    return list;
}

const WireAxis& wireAxis(Axis axis)
{
    for (const WireAxis& w : kWireAxes) {
        if (w.axis == axis)
            return w;
    }
    qFatal("E-LAB: axis %s is not one of the board's", qPrintable(axisName(axis)));
}

quint8 encodeStepByte(int dx, int dy, int dz)
{
    // SetFeedStepXYZ: Bit7 0, Bit6 StepZ, Bit5 StepY, Bit4 StepX, Bit3 0, Bit2 DirZ,
    // Bit1 DirY, Bit0 DirX; Dir set means one step in the negative direction.
    quint8 b = 0;
    const int d[3] = {dx, dy, dz};
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] != 0)
            b |= quint8(1u << (4 + axis));
        if (d[axis] < 0)
            b |= quint8(1u << axis);
    }
    return b;
}

Triple<int> decodeStepByte(quint8 byte)
{
    Triple<int> out{};
    for (int axis = 0; axis < 3; ++axis) {
        if (byte & (1u << (4 + axis)))
            out[axis] = (byte & (1u << axis)) ? -1 : 1;
    }
    return out;
}

bool isValidStepByte(quint8 byte)
{
    return (byte & 0x88) == 0;
}

namespace encode {
QByteArray requestMachineState()
{
    return QByteArray(1, ctrl::ENQ);
}
QByteArray requestAxeState()
{
    return QByteArray(1, ctrl::HT);
}
QByteArray requestTemperature()
{
    return QByteArray(1, ctrl::ETB);
}
QByteArray requestRelPosition()
{
    return QByteArray(1, ctrl::ETX);
}
QByteArray requestStart()
{
    return QByteArray(1, ctrl::LF);
}
QByteArray requestSync(int count)
{
    return QByteArray(qMax(1, count), ctrl::SYN);
}
QByteArray panicStop()
{
    return QByteArray(1, ctrl::BEL);
}
QByteArray stopMove()
{
    return QByteArray(1, ctrl::XOFF);
}
QByteArray flushBuffer()
{
    return QByteArray(1, ctrl::GS);
}
QByteArray clearPosition()
{
    return QByteArray(1, ctrl::RS);
}
QByteArray endOfFeed()
{
    return QByteArray(1, ctrl::CR);
}

QByteArray limitSwitchPolarity(const Triple<bool>& activeHigh)
{
    // Boolean parameters are whole bytes: $FF true, $00 false.
    return triple<quint8>(ctrl::SO,
                          {quint8(activeHigh[0] ? 0xFF : 0), quint8(activeHigh[1] ? 0xFF : 0),
                           quint8(activeHigh[2] ? 0xFF : 0)},
                          2);
}

QByteArray referenceSwitchPolarity(const Triple<bool>& activeHigh)
{
    return triple<quint8>(ctrl::DLE,
                          {quint8(activeHigh[0] ? 0xFF : 0), quint8(activeHigh[1] ? 0xFF : 0),
                           quint8(activeHigh[2] ? 0xFF : 0)},
                          2);
}

QByteArray ramp(RampKind kind, const Triple<quint16>& values)
{
    QByteArray out = triple(ctrl::ESC, values, 4);
    out.insert(1, char(kind));
    return out;
}

QByteArray feedSpeed(const Triple<quint16>& stepsPerS)
{
    return triple(ctrl::FS, stepsPerS, 4);
}
QByteArray drivePower(quint8 percent)
{
    return QByteArray(1, ctrl::STX) + hex(percent, 2);
}
QByteArray spindleRpm(quint32 rpm)
{
    return QByteArray(1, ctrl::SOH) + hex(rpm, 8) + '#';
}
QByteArray coolant(bool on)
{
    return QByteArray(1, ctrl::SI) + (on ? "FF" : "00");
}

QByteArray fastMoveXY(qint32 x, qint32 y)
{
    return QByteArray(1, ctrl::FF) + hex(quint32(x), 8) + ',' + hex(quint32(y), 8) + ';';
}

QByteArray fastMoveXYZ(const Triple<qint32>& steps)
{
    return triple(ctrl::EOT, steps, 8);
}
QByteArray fastMoveZ(qint32 z)
{
    return QByteArray(1, ctrl::BS) + hex(quint32(z), 8) + '.';
}
QByteArray feedStepsX(qint32 x)
{
    return QByteArray(1, ctrl::EM) + hex(quint32(x), 8) + ',';
}
QByteArray feedStepsY(qint32 y)
{
    return QByteArray(1, ctrl::SUB) + hex(quint32(y), 8) + ';';
}
QByteArray feedStepsZ(qint32 z)
{
    return QByteArray(1, ctrl::VT) + hex(quint32(z), 8) + '.';
}

QByteArray feedStep(quint8 stepByte)
{
    QByteArray out(1, ctrl::DC2);
    out += char(stepByte);
    return out;
}

QByteArray jogSpeed(const Triple<qint16>& stepsPerS)
{
    return triple(ctrl::DC4, stepsPerS, 4);
}
QByteArray referenceMove(const Triple<qint16>& d)
{
    return triple(ctrl::US, d, 4);
}
QByteArray velocityMove(const Triple<qint16>& v)
{
    return triple(ctrl::CAN, v, 4);
}
} // namespace encode

namespace encodeReply {
QByteArray machineState(quint16 word)
{
    return QByteArray(1, ctrl::ENQ) + hex(word, 4) + '#';
}
QByteArray axeState(quint8 byte)
{
    return QByteArray(1, ctrl::HT) + hex(byte, 2) + '#';
}
QByteArray temperature(quint8 celsius)
{
    return QByteArray(1, ctrl::ETB) + hex(celsius, 2) + '#';
}
QByteArray relPosition(const Triple<qint32>& remaining)
{
    return triple(ctrl::ETX, remaining, 8);
}
} // namespace encodeReply

// ---------------------------------------------------------------- ReplyDecoder

QList<Reply> ReplyDecoder::feed(const QByteArray& bytes)
{
    m_out.clear();
    for (char c : bytes) {
        // XON/XOFF are flow control the controller may send at any time (DC2 stream); they
        // are never payload characters, so they pass through even inside a frame.
        if (c == ctrl::XON || c == ctrl::XOFF) {
            Reply r;
            r.kind = c == ctrl::XON ? Reply::Kind::XOn : Reply::Kind::XOff;
            r.raw = QByteArray(1, c);
            m_out << r;
            continue;
        }
        if (isControl(c)) {
            // Every control byte starts a new frame: this is where decoding resynchronises.
            if (!m_buffer.isEmpty())
                flushInvalid(m_discarding ? m_discardReason
                                          : Codec::tr("reply interrupted by a new control byte"));
            if (c == ctrl::ACK || c == ctrl::NAK) {
                Reply r;
                r.kind = c == ctrl::ACK ? Reply::Kind::Ack : Reply::Kind::Nak;
                r.raw = QByteArray(1, c);
                m_out << r;
            } else if (replyPattern(c)) {
                m_buffer.append(c);
            } else {
                m_buffer.append(c);
                flushInvalid(Codec::tr("unexpected control byte"));
            }
            continue;
        }
        if (m_buffer.isEmpty() && !m_discarding)
            startDiscarding(Codec::tr("bytes outside a reply"));
        if (!m_discarding) {
            const int pos = int(m_buffer.size()) - 1;
            if (!fits(replyPattern(m_buffer.at(0)), pos, c)) {
                startDiscarding(Codec::tr("malformed reply"));
            } else {
                m_buffer.append(c);
                completeIfDone();
                continue;
            }
        }
        m_buffer.append(c);
        if (m_buffer.size() >= kMaxFrame)
            flushInvalid(m_discardReason);
    }
    return std::exchange(m_out, {});
}

void ReplyDecoder::startDiscarding(const QString& why)
{
    m_discarding = true;
    m_discardReason = why;
}

void ReplyDecoder::completeIfDone()
{
    const char code = m_buffer.at(0);
    const char* pattern = replyPattern(code);
    if (int(m_buffer.size()) - 1 < int(qstrlen(pattern)))
        return;
    Reply r;
    r.raw = m_buffer;
    const QByteArray payload = m_buffer.mid(1);
    std::array<qint64, 3> values{};
    parseGroups(pattern, payload, code == ctrl::ETX, &values);
    switch (code) {
    case ctrl::ENQ:
        r.kind = Reply::Kind::MachineState;
        r.machineState = quint16(values[0]);
        break;
    case ctrl::HT:
        r.kind = Reply::Kind::AxeState;
        r.axeState = quint8(values[0]);
        break;
    case ctrl::ETB:
        r.kind = Reply::Kind::Temperature;
        r.temperature = quint8(values[0]);
        break;
    case ctrl::ETX:
        r.kind = Reply::Kind::RelPosition;
        r.positions = {qint32(values[0]), qint32(values[1]), qint32(values[2])};
        break;
    default:
        break;
    }
    m_out << r;
    m_buffer.clear();
}

void ReplyDecoder::flushInvalid(const QString& why)
{
    Reply r;
    r.kind = Reply::Kind::Invalid;
    r.raw = m_buffer;
    r.error = why;
    m_out << r;
    m_buffer.clear();
    m_discarding = false;
}

// -------------------------------------------------------------- CommandDecoder

void CommandDecoder::reset()
{
    m_buffer.clear();
    m_expectStepByte = false;
}

QList<Command> CommandDecoder::feed(const QByteArray& bytes)
{
    m_out.clear();
    for (char c : bytes) {
        if (m_expectStepByte) {
            // <DC2> is followed by one raw data byte, whatever its value.
            m_expectStepByte = false;
            m_buffer.append(c);
            const quint8 step = quint8(c);
            Command cmd;
            cmd.code = ctrl::DC2;
            cmd.stepByte = step;
            cmd.raw = m_buffer;
            cmd.valid = isValidStepByte(step);
            if (!cmd.valid)
                cmd.error = Codec::tr("step byte has bit 7 or bit 3 set");
            m_out << cmd;
            m_buffer.clear();
            continue;
        }
        if (isControl(c)) {
            if (!m_buffer.isEmpty())
                complete(false, isControl(m_buffer.at(0))
                                    ? Codec::tr("command interrupted by a new control byte")
                                    : Codec::tr("bytes outside a command"));
            if (c == ctrl::DC2) {
                m_buffer.append(c);
                m_expectStepByte = true;
                continue;
            }
            const Format* format = commandFormat(c);
            m_buffer.append(c);
            if (!format) {
                complete(false, Codec::tr("unknown command byte"));
                continue;
            }
            tryParse();
            continue;
        }
        if (c == ' ' && !m_buffer.isEmpty() && isControl(m_buffer.at(0))) {
            ++m_unframed; // the manual's own examples have spaces ("<SO>FF, FF;00."): tolerated
            continue;
        }
        m_buffer.append(c);
        if (!isControl(m_buffer.at(0))) {
            if (m_buffer.size() >= kMaxFrame)
                complete(false, Codec::tr("bytes outside a command"));
            continue;
        }
        const Format* format = commandFormat(m_buffer.at(0));
        const int pos = int(m_buffer.size()) - 2;
        if (!fits(format->pattern, pos, c)) {
            complete(false, Codec::tr("malformed parameters"));
            continue;
        }
        tryParse();
    }
    return std::exchange(m_out, {});
}

bool CommandDecoder::tryParse()
{
    const char code = m_buffer.at(0);
    const Format* format = commandFormat(code);
    const char* pattern = format->pattern;
    if (int(m_buffer.size()) - 1 < int(qstrlen(pattern)))
        return false;
    Command cmd;
    cmd.code = code;
    cmd.raw = m_buffer;
    QByteArray payload = m_buffer.mid(1);
    if (code == ctrl::ESC) {
        cmd.ramp = RampKind(payload.at(0));
        cmd.valueCount = parseGroups(pattern + 1, payload.mid(1), false, &cmd.values);
    } else {
        cmd.valueCount = parseGroups(pattern, payload, format->isSigned, &cmd.values);
    }
    m_out << cmd;
    m_buffer.clear();
    return true;
}

void CommandDecoder::complete(bool valid, const QString& error)
{
    Command cmd;
    cmd.code = isControl(m_buffer.at(0)) ? m_buffer.at(0) : 0;
    cmd.valid = valid;
    cmd.error = error;
    cmd.raw = m_buffer;
    m_out << cmd;
    m_buffer.clear();
}

} // namespace stepdeck::elab
