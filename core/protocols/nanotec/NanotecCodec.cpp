#include "NanotecCodec.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

namespace {
bool isAsciiDigit(char c)
{
    return c >= '0' && c <= '9';
}

bool isKeywordChar(char c)
{
    // 1.2: long commands use 'A'..'Z', 'a'..'z' and '_' only; digits are not allowed.
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}

QByteArray addressText(int address)
{
    return address == kBroadcast ? QByteArray("*") : QByteArray::number(address);
}

QByteArray frame(int address, const QByteArray& body)
{
    return '#' + addressText(address) + body + '\r';
}

int leadingDigitCount(const QByteArray& text)
{
    int n = 0;
    while (n < text.size() && isAsciiDigit(text[n]))
        ++n;
    return n;
}
} // namespace

bool isValidAddress(int address)
{
    return address >= kMinAddress && address <= kMaxAddress;
}

// ---------------------------------------------------------------- encoder

namespace encode {
QByteArray command(int address, const QByteArray& cmd)
{
    if (!forbiddenReason(cmd).isEmpty())
        return {};
    return frame(address, cmd);
}

QByteArray command(int address, const QByteArray& cmd, qint64 value)
{
    // 1.1: the sign is optional for positive values; the manual's examples omit it.
    return command(address, cmd + QByteArray::number(value));
}

QByteArray read(int address, const QByteArray& cmd, int record)
{
    return frame(address, 'Z' + (record > 0 ? QByteArray::number(record) : QByteArray()) + cmd);
}

QByteArray readRecord(int address, int record)
{
    return read(address, "|", record);
}

QByteArray readErrorMemory(int address, int index)
{
    return frame(address, "ZE" + QByteArray::number(index));
}

QByteArray longRead(int address, const QByteArray& keyword)
{
    return frame(address, ':' + keyword);
}

QByteArray longWrite(int address, const QByteArray& keyword, qint64 value)
{
    return frame(address, ':' + keyword + '=' + QByteArray::number(value));
}
} // namespace encode

QString forbiddenReason(const QByteArray& body)
{
    QByteArray b = body;
    while (b.endsWith('\r'))
        b.chop(1);
    if (b.startsWith('|')) {
        qint64 v = 1;
        if (b.size() == 1 || !parseNumber(b.mid(1), &v) || v != 1)
            return Codec::tr("'|0' is never sent: the drive would stop answering (manual 6.4)");
    }
    if (b.startsWith("@A"))
        return Codec::tr("'@A' is never sent: it starts the bootloader (manual 5.32)");
    return {};
}

QByteArray commandKey(const QByteArray& body)
{
    if (body.isEmpty())
        return {};
    if (body.at(0) == ':') {
        int n = 1;
        while (n < body.size() && isKeywordChar(body.at(n)))
            ++n;
        return body.left(n);
    }
    if (body.at(0) == 'Z' && body.size() >= 2) {
        if (body.at(1) == 'E')
            return "ZE"; // the error slot index follows the E (5.15)
        const int digits = leadingDigitCount(body.mid(1));
        return body.left(qMin<qsizetype>(body.size(), 2 + digits));
    }
    if (body.startsWith("@A"))
        return "@A";
    return body.left(1);
}

bool parseNumber(const QByteArray& text, qint64* value)
{
    if (text.isEmpty())
        return false;
    const int i = (text[0] == '+' || text[0] == '-') ? 1 : 0;
    // At most 11 digits whatever the sign: formatSigned() adds a '+', so a limit on the whole
    // text let "949995009994" in that its own "+949995009994" could not be read again
    // (fuzz_nanotec_reply).
    if (i == text.size() || text.size() - i > 11)
        return false;
    for (int k = i; k < text.size(); ++k) {
        if (!isAsciiDigit(text[k]))
            return false;
    }
    bool ok = false;
    const qint64 v = text.mid(i).toLongLong(&ok);
    if (!ok)
        return false;
    *value = text[0] == '-' ? -v : v;
    return true;
}

QByteArray formatSigned(qint64 value)
{
    return (value < 0 ? QByteArray() : QByteArray("+")) + QByteArray::number(value);
}

std::optional<FirmwareInfo> parseFirmware(const QByteArray& text)
{
    // 5.22: hardware '_' interface '_' release date (tt-mm-jjjj).
    const QString s = QString::fromLatin1(text).trimmed();
    const QStringList parts = s.split(QLatin1Char('_'));
    if (parts.size() < 3 || parts[0].isEmpty())
        return std::nullopt;
    FirmwareInfo info;
    info.hardware = parts[0];
    info.interface = parts[1];
    info.date = parts.mid(2).join(QLatin1Char('_'));
    info.text = s;
    return info;
}

std::optional<qint64> RecordData::value(char cmd) const
{
    for (const auto& f : fields) {
        if (f.first == cmd)
            return f.second;
    }
    return std::nullopt;
}

// Section 4's table names repetitions 'w', but 6.14, the command index and the example reply
// of 6.4 ("...W+1P+0N+0") all say 'W', and no command 'w' exists: we read the table's 'w' as
// a typo for 'W'.
const QByteArray& recordFieldOrder()
{
    static const QByteArray order("psuonbdtWPN");
    return order;
}

QByteArray formatRecord(const RecordData& data)
{
    QByteArray out("Z");
    if (data.record > 0)
        out += QByteArray::number(data.record);
    for (const auto& f : data.fields)
        out += f.first + formatSigned(f.second);
    return out;
}

DriveState decodeStatus(qint64 word)
{
    DriveState s;
    s.ready = word & 0x01;
    s.zeroReached = word & 0x02;
    s.positionError = word & 0x04;
    s.input1WhileReady = word & 0x08;
    s.mode = int((word >> 4) & 0x07);
    return s;
}

quint8 encodeStatus(const DriveState& s)
{
    return quint8((s.ready ? 0x01 : 0) | (s.zeroReached ? 0x02 : 0) | (s.positionError ? 0x04 : 0) |
                  (s.input1WhileReady ? 0x08 : 0) | ((s.mode & 0x07) << 4));
}

QString motorModeName(int mode)
{
    switch (mode) {
    case 1:
        return Codec::tr("positioning");
    case 2:
        return Codec::tr("speed");
    case 3:
        return Codec::tr("flag positioning");
    case 4:
        return Codec::tr("clock-direction");
    case 5:
        return Codec::tr("analog");
    case 6:
        return Codec::tr("joystick");
    default:
        return Codec::tr("unused");
    }
}

QString describeStatus(qint64 word)
{
    const DriveState s = decodeStatus(word);
    QStringList parts;
    parts << (s.ready ? Codec::tr("ready") : Codec::tr("busy"));
    if (s.zeroReached)
        parts << Codec::tr("zero position reached");
    if (s.positionError)
        parts << Codec::tr("position error");
    if (s.input1WhileReady)
        parts << Codec::tr("input 1 still set while ready");
    parts << Codec::tr("mode %1").arg(motorModeName(s.mode));
    return parts.join(QStringLiteral(", "));
}

QString errorCodeName(int code)
{
    switch (code) {
    case 0:
        return QStringLiteral("none");
    case error::LowVoltage:
        return QStringLiteral("ERROR_LOWVOLTAGE");
    case error::Temperature:
        return QStringLiteral("ERROR_TEMP");
    case error::Driver:
        return QStringLiteral("ERROR_TMC");
    case error::Eeprom:
        return QStringLiteral("ERROR_EE");
    case error::Position:
        return QStringLiteral("ERROR_QEI");
    case error::Internal:
        return QStringLiteral("ERROR_INTERNAL");
    default:
        return QStringLiteral("0x%1").arg(code, 2, 16, QLatin1Char('0'));
    }
}

QString errorCodeDescription(int code)
{
    switch (code) {
    case 0:
        return Codec::tr("no error");
    case error::LowVoltage:
        return Codec::tr("undervoltage");
    case error::Temperature:
        return Codec::tr("over-temperature");
    case error::Driver:
        return Codec::tr("the driver chip reported an error");
    case error::Eeprom:
        return Codec::tr("nonsensical data in the EEPROM");
    case error::Position:
        return Codec::tr("position error");
    case error::Internal:
        return Codec::tr("internal error");
    default:
        return Codec::tr("unknown error code %1").arg(code);
    }
}

} // namespace stepdeck::nanotec
