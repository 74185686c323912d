#include "EmisGrammar.h"
#include <limits>

namespace stepdeck::emis {

namespace {
using K = Command::Kind;

bool parseDecimal(const QByteArray& text, qint64* out, bool allowSign = false)
{
    int i = 0;
    bool negative = false;
    if (allowSign && !text.isEmpty() && (text[0] == '-' || text[0] == '+')) {
        negative = text[0] == '-';
        i = 1;
    }
    if (i >= text.size() || text.size() - i > 18)
        return false; // 18 digits cannot overflow qint64
    qint64 value = 0;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c < '0' || c > '9')
            return false;
        value = value * 10 + (c - '0');
    }
    *out = negative ? -value : value;
    return true;
}

// "x32" -> X, 32. upper: the letter was upper case (absolute target, 9.11).
bool axisValue(const QByteArray& field, Axis* axis, qint64* value, bool allowSign = false,
               bool* upper = nullptr)
{
    if (field.size() < 2)
        return false;
    const auto a = axisFromLetter(field[0]);
    if (!a || !parseDecimal(field.mid(1), value, allowSign))
        return false;
    *axis = *a;
    if (upper)
        *upper = field[0] >= 'A' && field[0] <= 'Z';
    else if (field[0] >= 'A' && field[0] <= 'Z')
        return false; // only vector targets know upper-case letters
    return true;
}

Command invalid(const QByteArray& text, const QString& why)
{
    Command c;
    c.text = text;
    c.error = why;
    return c;
}

Command make(K kind, const QByteArray& text)
{
    Command c;
    c.kind = kind;
    c.text = text;
    return c;
}

QString malformed(const QByteArray& text)
{
    return Grammar::tr("'%1' is malformed (see the SMC-IC4 manual, chapter 9)")
        .arg(QString::fromLatin1(text));
}

// "<v>" or ",<a><v>" after a prefix (9.4 "#S200" / "#S,x200", 9.5 "#E1,1000" / "#E1,x1000").
Command allOrAxis(K kind, const QByteArray& text, const QByteArray& rest)
{
    Command c = make(kind, text);
    Axis axis = Axis::X;
    if (parseDecimal(rest, &c.value))
        return c;
    if (axisValue(rest, &axis, &c.value)) {
        c.axis = axis;
        return c;
    }
    return invalid(text, malformed(text));
}

Command parseNumbered(K kind, const QByteArray& text, const QByteArray& digits)
{
    Command c = make(kind, text);
    qint64 n = 0;
    if (!parseDecimal(digits, &n) || n > 99)
        return invalid(text, malformed(text));
    c.number = int(n);
    return c;
}

Command parseHome(const QByteArray& text)
{
    // "$Hxyzu", "$Hxyzu,a" (9.9) and "$H,x" (9.17 example).
    QByteArray rest = text.mid(2);
    if (rest.startsWith(','))
        rest = rest.mid(1);
    const QList<QByteArray> parts = rest.split(',');
    Command c = make(K::Home, text);
    if (parts.size() > 2 || (parts.size() == 2 && parts[1] != "a") || parts[0].isEmpty())
        return invalid(text, malformed(text));
    c.simultaneous = parts.size() == 2;
    for (char letter : parts[0]) {
        const auto axis = axisFromLetter(letter);
        if (!axis || (letter >= 'A' && letter <= 'Z') || c.axes.contains(*axis))
            return invalid(text, malformed(text));
        c.axes << *axis;
    }
    return c;
}

Command parseVector(const QByteArray& text)
{
    const QList<QByteArray> fields = text.mid(3).split(',');
    Command c = make(K::Vector, text);
    for (const QByteArray& f : fields) {
        VectorTarget t;
        if (!axisValue(f, &t.axis, &t.value, true, &t.absolute))
            return invalid(text, malformed(text));
        for (const VectorTarget& other : c.targets) {
            if (other.axis == t.axis)
                return invalid(text, Grammar::tr("'%1' names axis %2 twice")
                                         .arg(QString::fromLatin1(text), axisName(t.axis)));
        }
        c.targets << t;
    }
    return c;
}

Command parseHeader(const QByteArray& text)
{
    // "IJ7,1 Eingang 7: Referenzfahrt X-Motor" (9.17), closed by <STX>.
    const qsizetype comma = text.indexOf(',');
    if (!text.startsWith("IJ") || comma < 3 || text.mid(comma + 1, 1) != "1")
        return invalid(text, malformed(text));
    Command c = parseNumbered(K::ProgramHeader, text, text.mid(2, comma - 2));
    if (c.kind == K::Invalid)
        return c;
    QByteArray title = text.mid(comma + 2);
    if (title.startsWith(' '))
        title = title.mid(1);
    c.title = title;
    return c;
}

Command parseStar(const QByteArray& text)
{
    if (text == "*PRSYS")
        return make(K::ReadSystem, text);
    if (text == "*PESYS")
        return make(K::ClearSystem, text);
    if (text.startsWith("*PWIN"))
        return parseNumbered(K::ProgramOpen, text, text.mid(5));
    if (text.startsWith("*PEIN"))
        return parseNumbered(K::ProgramErase, text, text.mid(5));
    return invalid(text, Grammar::tr("unknown command '%1'").arg(QString::fromLatin1(text)));
}

Command parseHash(const QByteArray& text)
{
    if (text.startsWith("##")) {
        QString error;
        const auto entry = parseSystemEntry(text.mid(2), &error);
        if (!entry)
            return invalid(text, error);
        Command c = make(K::SystemWrite, text);
        c.system = *entry;
        return c;
    }
    if (text.startsWith("#S"))
        return allOrAxis(K::StartSpeed, text,
                         text.mid(2).startsWith(',') ? text.mid(3) : text.mid(2));
    if (text.startsWith("#E1,"))
        return allOrAxis(K::WorkSpeed, text, text.mid(4));
    if (text.startsWith("#E9,")) {
        Command c = make(K::ReferenceSpeed, text);
        return parseDecimal(text.mid(4), &c.value) ? c : invalid(text, malformed(text));
    }
    if (text.startsWith("#R")) {
        Command c = make(K::Ramp, text);
        return parseDecimal(text.mid(2), &c.value) ? c : invalid(text, malformed(text));
    }
    if (text.startsWith("#O")) {
        // "#Ox,10" (9.10)
        Command c = make(K::ReferenceOffset, text);
        const auto axis = text.size() > 3 ? axisFromLetter(text[2]) : std::nullopt;
        if (!axis || text[2] < 'a' || text[3] != ',' || !parseDecimal(text.mid(4), &c.value))
            return invalid(text, malformed(text));
        c.axis = *axis;
        return c;
    }
    return invalid(text, Grammar::tr("unknown command '%1'").arg(QString::fromLatin1(text)));
}

Command parseCurrent(const QByteArray& text)
{
    // "c,x100,20" (9.8)
    const QList<QByteArray> f = text.split(',');
    Command c = make(K::Current, text);
    Axis axis = Axis::X;
    if (f.size() != 3 || !axisValue(f[1], &axis, &c.value) || !parseDecimal(f[2], &c.idle))
        return invalid(text, malformed(text));
    c.axis = axis;
    return c;
}

Command parseLine(const QByteArray& text)
{
    if (text == "@V")
        return make(K::Version, text);
    if (text == "@IG")
        return make(K::AllInputs, text);
    if (text.startsWith("@I"))
        return parseNumbered(K::Input, text, text.mid(2));
    if (text.startsWith('#'))
        return parseHash(text);
    if (text.startsWith('*'))
        return parseStar(text);
    if (text.startsWith("$H"))
        return parseHome(text);
    if (text.startsWith("L1,"))
        return parseVector(text);
    if (text == "IP0" || text == "IP1") {
        Command c = make(K::Interpolation, text);
        c.on = text == "IP1";
        return c;
    }
    if (text.startsWith("D,")) {
        Command c = make(K::StepResolution, text);
        Axis axis = Axis::X;
        if (!axisValue(text.mid(2), &axis, &c.value))
            return invalid(text, malformed(text));
        c.axis = axis;
        return c;
    }
    if (text.startsWith("c,"))
        return parseCurrent(text);
    if (text.startsWith('W')) {
        Command c = make(K::Wait, text);
        return parseDecimal(text.mid(1), &c.value) ? c : invalid(text, malformed(text));
    }
    if (text.startsWith('A')) {
        // "A1,1" (9.3)
        const QList<QByteArray> f = text.mid(1).split(',');
        Command c = parseNumbered(K::Output, text, f.value(0));
        if (c.kind == K::Invalid || f.size() != 2 || (f[1] != "0" && f[1] != "1"))
            return invalid(text, malformed(text));
        c.on = f[1] == "1";
        return c;
    }
    return invalid(text, Grammar::tr("unknown command '%1'").arg(QString::fromLatin1(text)));
}

QString outOfRange(const Command& c, qint64 value, qint64 minimum, qint64 maximum)
{
    if (value >= minimum && value <= maximum)
        return {};
    return Grammar::tr("%1: value %2 is out of range (allowed: %3..%4)")
        .arg(QString::fromLatin1(c.text))
        .arg(value)
        .arg(minimum)
        .arg(maximum);
}

QString firstError(std::initializer_list<QString> errors)
{
    for (const QString& e : errors) {
        if (!e.isEmpty())
            return e;
    }
    return {};
}

QString speedsError(const Command& c, const QMap<Axis, qint64>& values)
{
    for (qint64 v : values) {
        if (QString e = outOfRange(c, v, limits::kSpeedMin, limits::kSpeedMax); !e.isEmpty())
            return e;
    }
    return {};
}

QString systemRangeError(const Command& c)
{
    const SystemEntry& s = c.system;
    switch (s.key) {
    case SystemEntry::Key::StepResolution:
        for (qint64 v : s.values) {
            if (!limits::isStepResolution(v))
                return Grammar::tr("%1: %2 is not a step resolution (1, 2, 4, ..., 256)")
                    .arg(QString::fromLatin1(c.text))
                    .arg(v);
        }
        return {};
    case SystemEntry::Key::Currents:
        for (Axis a : s.values.keys()) {
            if (QString e = firstError({outOfRange(c, s.values[a], 0, limits::kRunCurrentMax),
                                        outOfRange(c, s.idle[a], 0, limits::kIdleCurrentMax)});
                !e.isEmpty())
                return e;
        }
        return {};
    case SystemEntry::Key::ReferenceSwitch:
        return {};
    case SystemEntry::Key::StartSpeed:
    case SystemEntry::Key::WorkSpeed:
    case SystemEntry::Key::ReferenceSpeed:
        return speedsError(c, s.values);
    case SystemEntry::Key::Ramp:
        return outOfRange(c, s.ramp, limits::kRampMin, limits::kRampMax);
    case SystemEntry::Key::SmcFlex:
        return firstError({outOfRange(c, s.flexStart, limits::kSpeedMin, limits::kSpeedMax),
                           outOfRange(c, s.flexWork, limits::kSpeedMin, limits::kSpeedMax),
                           outOfRange(c, s.flexRamp, limits::kRampMin, limits::kRampMax)});
    }
    return {};
}
} // namespace

bool limits::isStepResolution(qint64 microsteps)
{
    for (qint64 v = 1; v <= 256; v *= 2) {
        if (v == microsteps)
            return true;
    }
    return false;
}

Command parseCommand(const QByteArray& text, char terminator)
{
    if (terminator == kEtx) {
        return text.isEmpty()
                   ? make(K::ProgramEnd, text)
                   : invalid(text,
                             Grammar::tr("text before <ETX>: '%1'").arg(QString::fromLatin1(text)));
    }
    for (char c : text) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            return invalid(text, Grammar::tr("a command holds printable ASCII characters only"));
    }
    if (terminator == kStx)
        return parseHeader(text);
    if (text.isEmpty())
        return invalid(text, Grammar::tr("empty command"));
    if (text.startsWith("IJ"))
        return invalid(text, Grammar::tr("a program header ends with <STX>, not <CR>"));
    return parseLine(text);
}

QString rangeError(const Command& c)
{
    switch (c.kind) {
    case K::Input:
    case K::ProgramOpen:
    case K::ProgramErase:
        return outOfRange(c, c.number, 1, kInputCount);
    case K::ProgramHeader:
        if (c.title.size() > limits::kTitleMax)
            return Grammar::tr("program title longer than %1 characters").arg(limits::kTitleMax);
        return outOfRange(c, c.number, 1, kInputCount);
    case K::Output:
        return outOfRange(c, c.number, 1, kOutputCount);
    case K::StartSpeed:
    case K::WorkSpeed:
    case K::ReferenceSpeed:
        return outOfRange(c, c.value, limits::kSpeedMin, limits::kSpeedMax);
    case K::Ramp:
        return outOfRange(c, c.value, limits::kRampMin, limits::kRampMax);
    case K::StepResolution:
        return limits::isStepResolution(c.value)
                   ? QString()
                   : Grammar::tr("%1: %2 is not a step resolution (1, 2, 4, ..., 256)")
                         .arg(QString::fromLatin1(c.text))
                         .arg(c.value);
    case K::Current:
        return firstError({outOfRange(c, c.value, 0, limits::kRunCurrentMax),
                           outOfRange(c, c.idle, 0, limits::kIdleCurrentMax)});
    case K::ReferenceOffset:
        return outOfRange(c, c.value, 0, limits::kOffsetMax);
    case K::Wait:
        return outOfRange(c, c.value, 0, limits::kWaitMax);
    case K::Vector:
        for (const VectorTarget& t : c.targets) {
            if (QString e = outOfRange(c, t.value, -limits::kVectorMax, limits::kVectorMax);
                !e.isEmpty())
                return e;
        }
        return {};
    case K::SystemWrite:
        return systemRangeError(c);
    default:
        return {};
    }
}

QString programRefusal(const Command& c)
{
    switch (c.kind) {
    case K::Output:
    case K::StartSpeed:
    case K::WorkSpeed:
    case K::ReferenceSpeed:
    case K::Ramp:
    case K::StepResolution:
    case K::Current:
    case K::Home:
    case K::ReferenceOffset:
    case K::Vector:
    case K::Interpolation:
    case K::Wait:
        return {};
    case K::Invalid:
        return c.error;
    default:
        return Grammar::tr("'%1' cannot be part of an input program: queries, system parameters "
                           "and program commands are not stored")
            .arg(QString::fromLatin1(c.text));
    }
}

QString validateProgramLine(const QByteArray& line)
{
    const Command c = parseCommand(line);
    if (c.kind == K::Invalid)
        return c.error;
    if (QString e = programRefusal(c); !e.isEmpty())
        return e;
    return rangeError(c);
}

// ---------------------------------------------------------------- device-side framing

void CommandDecoder::reset()
{
    m_skipped = 0;
    m_buffer.clear();
    m_discarding = false;
}

QList<CommandDecoder::Frame> CommandDecoder::feed(const QByteArray& bytes)
{
    QList<Frame> out;
    for (char c : bytes) {
        if (c == kCr || c == kStx || c == kEtx) {
            Frame f;
            f.terminator = c;
            f.overlong = m_discarding;
            f.text = m_discarding ? QByteArray() : m_buffer;
            m_buffer.clear();
            m_discarding = false;
            if (f.overlong || !f.text.isEmpty() || c != kCr)
                out << f; // an empty <CR> line (CR LF CR) is no command
            else
                ++m_skipped;
            continue;
        }
        if (m_discarding || (m_buffer.isEmpty() && (c == '\n' || c == ' ' || c == '\t'))) {
            ++m_skipped; // an overlong tail; LF of a CR LF terminal, blanks between commands
            continue;
        }
        m_buffer += c;
        if (m_buffer.size() > kMaxFrame) {
            m_skipped += m_buffer.size();
            m_buffer.clear();
            m_discarding = true;
        }
    }
    return out;
}

} // namespace stepdeck::emis
