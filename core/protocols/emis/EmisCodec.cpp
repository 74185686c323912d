#include "EmisCodec.h"
#include <QCoreApplication>
#include <QMap>

namespace stepdeck::emis {

namespace {
QByteArray num(qint64 value)
{
    return QByteArray::number(value);
}

bool isBlank(char c)
{
    return c == ' ' || c == '\r' || c == '\n' || c == '\t';
}

bool isText(char c)
{
    const auto b = static_cast<unsigned char>(c);
    return (b >= 0x20 && b < 0x7F) || isBlank(c);
}
} // namespace

namespace {
// The manual's axes x, y, z, u in that order: their arrivals <DC1> .. <DC4> (9, replies; 9.9:
// "<DC2>, <DC3>, <DC4> bei Y-, Z-, und U-Motor") and their reference switches on inputs 1 .. 4
// (5.2.2; 9.14's example: "X-Motor: Referenzschalter am Eingang 1").
constexpr WireAxis kWireAxes[] = {
    {Axis::X, 'x', 1},
    {Axis::Y, 'y', 2},
    {Axis::Z, 'z', 3},
    {Axis::U, 'u', 4},
};
const WireAxis* find(Axis axis)
{
    for (const WireAxis& w : kWireAxes) {
        if (w.axis == axis)
            return &w;
    }
    return nullptr;
}
} // namespace

const QList<Axis>& emisAxes()
{
    static const QList<Axis> list = [] {
        QList<Axis> out;
        for (const WireAxis& w : kWireAxes)
            out << w.axis;
        return out;
    }();
    return list;
}

int axisNumber(Axis axis)
{
    const WireAxis* w = find(axis);
    if (!w)
        qFatal("EMIS: axis %s is not one of the controller's", qPrintable(axisName(axis)));
    return w->number;
}

std::optional<Axis> axisOfNumber(int number)
{
    for (const WireAxis& w : kWireAxes) {
        if (w.number == number)
            return w.axis;
    }
    return std::nullopt;
}

char axisLetter(Axis axis)
{
    const WireAxis* w = find(axis);
    return w ? w->letter : '?';
}

std::optional<Axis> axisFromLetter(char letter)
{
    const char lower = (letter >= 'A' && letter <= 'Z') ? char(letter - 'A' + 'a') : letter;
    for (const WireAxis& w : kWireAxes) {
        if (w.letter == lower)
            return w.axis;
    }
    return std::nullopt;
}

char arrivalCode(Axis axis)
{
    return char(kDc1 + axisNumber(axis) - 1);
}

// ---------------------------------------------------------------- encoder

namespace encode {
QByteArray version()
{
    return "@V\r";
}

QByteArray input(int number)
{
    return "@I" + num(number) + kCr;
}

QByteArray allInputs()
{
    return "@IG\r";
}

QByteArray output(int number, bool on)
{
    return 'A' + num(number) + ',' + (on ? '1' : '0') + kCr;
}

QByteArray startSpeedAll(qint64 stepsPerS)
{
    return "#S" + num(stepsPerS) + kCr;
}

QByteArray startSpeed(Axis axis, qint64 stepsPerS)
{
    return QByteArray("#S,") + axisLetter(axis) + num(stepsPerS) + kCr;
}

QByteArray workSpeedAll(qint64 stepsPerS)
{
    return "#E1," + num(stepsPerS) + kCr;
}

QByteArray workSpeed(Axis axis, qint64 stepsPerS)
{
    return QByteArray("#E1,") + axisLetter(axis) + num(stepsPerS) + kCr;
}

QByteArray referenceSpeed(qint64 stepsPerS)
{
    return "#E9," + num(stepsPerS) + kCr;
}

QByteArray ramp(qint64 ms)
{
    return "#R" + num(ms) + kCr;
}

QByteArray stepResolution(Axis axis, qint64 microsteps)
{
    return QByteArray("D,") + axisLetter(axis) + num(microsteps) + kCr;
}

QByteArray current(Axis axis, qint64 runPercent, qint64 idlePercent)
{
    return QByteArray("c,") + axisLetter(axis) + num(runPercent) + ',' + num(idlePercent) + kCr;
}

QByteArray home(const QList<Axis>& axes, bool simultaneous)
{
    QByteArray out("$H");
    for (Axis axis : emisAxes()) {
        if (axes.contains(axis))
            out += axisLetter(axis);
    }
    if (simultaneous)
        out += ",a";
    return out + kCr;
}

QByteArray referenceOffset(Axis axis, qint64 steps)
{
    return QByteArray("#O") + axisLetter(axis) + ',' + num(steps) + kCr;
}

QByteArray vector(const QList<VectorTarget>& targets)
{
    QByteArray out("L1");
    for (const VectorTarget& t : targets) {
        const char letter = axisLetter(t.axis);
        out += ',';
        out += t.absolute ? char(letter - 'a' + 'A') : letter;
        out += num(t.value);
    }
    return out + kCr;
}

QByteArray interpolation(bool on)
{
    return on ? "IP1\r" : "IP0\r";
}

QByteArray wait(qint64 ms)
{
    return 'W' + num(ms) + kCr;
}

QByteArray systemPerAxis(const QByteArray& key, const QMap<Axis, qint64>& values)
{
    QByteArray out = "##" + key;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        out += ',' + QByteArray(1, axisLetter(it.key())) + num(it.value());
    return out + kCr;
}

QByteArray systemCurrents(const QMap<Axis, QPair<qint64, qint64>>& runIdle)
{
    QByteArray out = "##c";
    for (auto it = runIdle.cbegin(); it != runIdle.cend(); ++it) {
        out += ',' + QByteArray(1, axisLetter(it.key())) + num(it.value().first) + ',' +
               num(it.value().second);
    }
    return out + kCr;
}

QByteArray systemReferenceSwitches(const QMap<Axis, bool>& normallyClosed)
{
    QByteArray out = "##REFSW";
    for (auto it = normallyClosed.cbegin(); it != normallyClosed.cend(); ++it)
        out += ',' + QByteArray(1, axisLetter(it.key())) + (it.value() ? "NC" : "NO");
    return out + kCr;
}

QByteArray systemRamp(qint64 ms)
{
    return "##R," + num(ms) + kCr;
}

QByteArray readSystem()
{
    return "*PRSYS\r";
}

QByteArray clearSystem()
{
    return "*PESYS\r";
}

QByteArray programOpen(int input)
{
    return "*PWIN" + num(input) + kCr;
}

QByteArray programHeader(int input, const QByteArray& title)
{
    // 9.17 prints "IJ7,1 Eingang 7: Referenzfahrt X-Motor <STX>"; the blank before <STX> is
    // read as the manual's notation (as in "<NAK> <DC1>"), not as part of the title.
    return "IJ" + num(input) + ",1 " + title + kStx;
}

QByteArray programLine(const QByteArray& command)
{
    return command + kCr;
}

QByteArray programEnd()
{
    return QByteArray(1, kEtx);
}

QByteArray programErase(int input)
{
    return "*PEIN" + num(input) + kCr;
}
} // namespace encode

// ---------------------------------------------------------------- decoder

void ReplyDecoder::reset()
{
    m_skipped = 0;
    m_text.clear();
    m_garbage.clear();
    m_discarding = false;
}

void ReplyDecoder::flushGarbage(QList<Event>* out)
{
    if (m_garbage.isEmpty())
        return;
    Event e;
    e.kind = Event::Kind::Invalid;
    e.raw = m_garbage;
    e.error = tr("%n byte(s) that are neither text nor a reply terminator", nullptr,
                 int(m_garbage.size()));
    out->append(e);
    m_garbage.clear();
}

QList<Event> ReplyDecoder::feed(const QByteArray& bytes)
{
    QList<Event> out;
    for (char c : bytes) {
        if (c >= kDc1 && c < kDc1 + 4) {
            flushGarbage(&out);
            Event e;
            e.kind = Event::Kind::Arrived;
            e.axis = *axisOfNumber(c - kDc1 + 1); // <DC1> .. <DC4>: 1 .. 4
            out.append(e);
            continue;
        }
        if (c == kAck || c == kNak || c == kBel) {
            flushGarbage(&out);
            if (m_discarding) {
                m_discarding = false; // the overlong text's own terminator
                ++m_skipped;
                continue;
            }
            Event e;
            e.kind =
                c == kAck ? Event::Kind::Ack : (c == kNak ? Event::Kind::Nak : Event::Kind::Bell);
            e.text = m_text.trimmed();
            m_skipped += m_text.size() - e.text.size();
            m_text.clear();
            out.append(e);
            continue;
        }
        if (!isText(c)) {
            // Garbage spoils the text gathered so far: report both, start afresh behind it.
            m_garbage += m_text;
            m_text.clear();
            m_garbage += c;
            if (m_garbage.size() > kMaxText)
                flushGarbage(&out);
            continue;
        }
        flushGarbage(&out);
        if (m_discarding || (m_text.isEmpty() && isBlank(c))) {
            ++m_skipped; // an overlong tail, or blanks between terminators ("<NAK> <DC1>")
            continue;
        }
        m_text += c;
        if (m_text.size() > kMaxText) {
            Event e;
            e.kind = Event::Kind::Invalid;
            e.raw = m_text;
            e.error = tr("reply text longer than %1 bytes without a terminator").arg(kMaxText);
            out.append(e);
            m_text.clear();
            m_discarding = true;
        }
    }
    return out;
}

// ---------------------------------------------------------------- answers

QByteArray payloadAfterEcho(const QByteArray& text, const QByteArray& echo)
{
    if (echo.isEmpty())
        return text.trimmed();
    const qsizetype at = text.lastIndexOf(echo);
    return at < 0 ? text.trimmed() : text.mid(at + echo.size()).trimmed();
}

std::optional<QString> parseVersion(const QByteArray& text)
{
    const QByteArray v = payloadAfterEcho(text, "@V");
    if (v.isEmpty())
        return std::nullopt;
    return QString::fromLatin1(v);
}

std::optional<QList<bool>> parseAllInputs(const QByteArray& text)
{
    QByteArray bits = payloadAfterEcho(text, "@IG");
    bits.replace(' ', QByteArray()); // tolerate "1000 0000"
    if (bits.size() != kInputCount)
        return std::nullopt;
    QList<bool> levels;
    for (char c : bits) {
        if (c != '0' && c != '1')
            return std::nullopt;
        levels << (c == '1');
    }
    return levels;
}

std::optional<bool> parseInput(const QByteArray& text, int number)
{
    const QByteArray level = payloadAfterEcho(text, "@I" + QByteArray::number(number));
    if (level == "0" || level == "1")
        return level == "1";
    return std::nullopt;
}

bool isReady(const QByteArray& text)
{
    return text.trimmed().compare("Ready!", Qt::CaseInsensitive) == 0;
}

} // namespace stepdeck::emis
