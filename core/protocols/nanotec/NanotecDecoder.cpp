// Streaming decoders of the Nanotec ASCII protocol (declared in NanotecCodec.h).
#include "NanotecCodec.h"
#include <QCoreApplication>

namespace stepdeck::nanotec {

namespace {
bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

int leadingDigits(const QByteArray& text, int from = 0)
{
    int n = from;
    while (n < text.size() && isDigit(text[n]))
        ++n;
    return n - from;
}

Reply invalid(const QByteArray& raw, const QString& why)
{
    Reply r;
    r.kind = Reply::Kind::Invalid;
    r.raw = raw;
    r.error = why;
    return r;
}

// One "<cmd><value>" pair of a read reply or record string: the value is an optional sign
// followed by digits; it ends where the next command character starts.
struct Pair
{
    char cmd = 0;
    QByteArray text;
};

QList<Pair> splitPairs(const QByteArray& text)
{
    QList<Pair> out;
    int i = 0;
    while (i < text.size()) {
        Pair p;
        p.cmd = text[i++];
        const int start = i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-') && i + 1 < text.size() &&
            isDigit(text[i + 1]))
            ++i;
        i += leadingDigits(text, i);
        p.text = text.mid(start, i - start);
        out << p;
    }
    return out;
}

// Body "Z..." after the address: a value read back (5.19), an error slot (5.15) or a
// whole record (6.4).
Reply parseZ(const QByteArray& raw, const QByteArray& body, Reply r)
{
    if (body.size() < 2)
        return invalid(raw, Codec::tr("read reply without a command"));
    if (body.at(1) == 'E') {
        // "ZE<slot><code>": unambiguous only when the code carries a sign ("ZE5+8").
        r.kind = Reply::Kind::Read;
        r.key = "ZE";
        const QByteArray rest = body.mid(2);
        const int digits = leadingDigits(rest);
        if (digits == 0)
            return invalid(raw, Codec::tr("error memory reply without a slot number"));
        r.text = rest;
        if (digits < rest.size()) {
            qint64 code = 0;
            if (!parseNumber(rest.mid(digits), &code))
                return invalid(raw, Codec::tr("malformed error memory reply"));
            r.index = rest.left(digits).toInt();
            r.value = code;
        }
        return r;
    }
    const int digits = leadingDigits(body, 1);
    // 5.19 / 6.4: a record number names an EEPROM record 1..32 ("Z5s", "Z5|"); no number is
    // the record in RAM. "Z0..", "Z05.." or "Z33.." are nothing the drive sends.
    if (digits > 0) {
        r.record = digits <= 2 && body.at(1) != '0' ? body.mid(1, digits).toInt() : 0;
        if (r.record < 1 || r.record > kRecordCount)
            return invalid(raw, Codec::tr("read reply for record '%1' (records are 1..%2)")
                                    .arg(QString::fromLatin1(body.mid(1, digits)))
                                    .arg(kRecordCount));
    }
    const QList<Pair> pairs = splitPairs(body.mid(1 + digits));
    if (pairs.isEmpty())
        return invalid(raw, Codec::tr("read reply without a command"));
    if (pairs.size() == 1) {
        qint64 v = 0;
        if (!parseNumber(pairs[0].text, &v))
            return invalid(raw, Codec::tr("read reply without a numeric value"));
        r.kind = Reply::Kind::Read;
        r.key = body.left(1 + digits) + pairs[0].cmd;
        r.text = pairs[0].text;
        r.value = v;
        return r;
    }
    r.kind = Reply::Kind::Record;
    r.key = body.left(1 + digits) + '|';
    r.recordData.record = r.record;
    for (const Pair& p : pairs) {
        // 6.4 sends "all settings of the record": the ones section 4 lists, each once.
        if (!recordFieldOrder().contains(p.cmd))
            return invalid(raw,
                           Codec::tr("'%1' is not a record setting (section 4)").arg(QChar(p.cmd)));
        if (r.recordData.value(p.cmd))
            return invalid(raw, Codec::tr("record setting '%1' given twice").arg(QChar(p.cmd)));
        qint64 v = 0;
        if (!parseNumber(p.text, &v))
            return invalid(raw, Codec::tr("malformed record string"));
        r.recordData.fields << qMakePair(p.cmd, v);
    }
    return r;
}

Reply parseLong(const QByteArray& raw, const QByteArray& body, Reply r)
{
    if (body == ":?" || body.endsWith('?')) {
        r.kind = Reply::Kind::LongUnknown; // 1.2: "ID:?"
        r.key = ":?";
        return r;
    }
    r.key = commandKey(body);
    if (r.key.size() < 2)
        return invalid(raw, Codec::tr("long reply without a keyword"));
    QByteArray rest = body.mid(r.key.size());
    if (!rest.isEmpty() && rest[0] == '=') {
        r.assignment = true;
        rest = rest.mid(1);
    }
    qint64 v = 0;
    if (!parseNumber(rest, &v))
        return invalid(raw, Codec::tr("long reply without a numeric value"));
    r.kind = Reply::Kind::Long;
    r.text = rest;
    r.value = v;
    return r;
}
} // namespace

Reply ReplyDecoder::parse(const QByteArray& frame)
{
    for (char c : frame) {
        if (c < 0x20 || c >= 0x7F)
            return invalid(frame, Codec::tr("non-ASCII bytes in reply"));
    }
    if (frame.startsWith('#')) {
        Reply r;
        r.kind = Reply::Kind::HostEcho; // a half-duplex adapter echoing our own frame
        r.raw = frame;
        return r;
    }
    Reply r;
    r.raw = frame;
    const int digits = leadingDigits(frame);
    if (digits > 3)
        return invalid(frame, Codec::tr("address with more than three digits"));
    if (digits > 0) {
        r.address = frame.left(digits).toInt();
        if (r.address < 1 || r.address > 255)
            return invalid(frame, Codec::tr("reply from invalid address %1").arg(r.address));
    }
    const QByteArray body = frame.mid(digits);
    if (body.isEmpty())
        return invalid(frame, Codec::tr("reply without a command"));
    if (digits == 0 && body.at(0) != 'Z')
        return invalid(frame, Codec::tr("reply without an address"));
    if (body.at(0) == ':')
        return parseLong(frame, body, r);
    if (body.endsWith('?')) {
        r.kind = Reply::Kind::Unknown; // 1.1: "001/?"
        r.key = commandKey(body.chopped(1));
        return r;
    }
    if (body.at(0) == 'v' && body.size() > 1 && body.at(1) == ' ') {
        const auto fw = parseFirmware(body.mid(2));
        if (!fw)
            return invalid(frame, Codec::tr("malformed firmware string"));
        r.kind = Reply::Kind::Firmware;
        r.key = "v";
        r.firmware = *fw;
        return r;
    }
    if (body.at(0) == 'Z')
        return parseZ(frame, body, r);
    r.kind = Reply::Kind::Echo;
    r.key = body.left(1);
    r.text = body.mid(1);
    if (!r.text.isEmpty()) {
        qint64 v = 0;
        if (!parseNumber(r.text, &v))
            return invalid(frame, Codec::tr("echo with a non-numeric value"));
        r.value = v;
    }
    return r;
}

QList<Reply> ReplyDecoder::feed(const QByteArray& bytes)
{
    QList<Reply> out;
    for (char c : bytes) {
        if (m_discarding) {
            ++m_unframed;
            if (c == '\r')
                m_discarding = false;
            continue;
        }
        if (c == '\n' || (c == '\0' && m_buffer.isEmpty())) {
            ++m_unframed;
            continue; // line feeds some adapters add; idle-line zeros
        }
        if (c == '\r') {
            ++m_unframed;
            if (!m_buffer.isEmpty())
                out << parse(m_buffer);
            m_buffer.clear();
            continue;
        }
        m_buffer += c;
        if (m_buffer.size() > kMaxFrame) {
            out << invalid(m_buffer, Codec::tr("reply longer than %1 bytes").arg(kMaxFrame));
            m_buffer.clear();
            m_discarding = true; // resynchronise at the next CR
        }
    }
    return out;
}

void ReplyDecoder::reset()
{
    m_buffer.clear();
    m_discarding = false;
}

// ---------------------------------------------------------------- device side

QList<Command> CommandDecoder::feed(const QByteArray& bytes)
{
    QList<Command> out;
    auto fail = [&](const QString& why) {
        Command c;
        c.valid = false;
        c.error = why;
        c.raw = m_buffer;
        out << c;
    };
    for (char ch : bytes) {
        if (ch == '#') {
            if (m_inFrame && m_buffer.size() > 1)
                fail(Codec::tr("frame interrupted by a new '#'"));
            else if (m_inFrame)
                ++m_unframed; // "##": the first '#' began an empty frame
            m_buffer = "#";
            m_inFrame = true;
            continue;
        }
        if (!m_inFrame) {
            ++m_unframed;
            continue; // 1.1: a command always begins with '#'
        }
        if (ch != '\r') {
            m_buffer += ch;
            if (m_buffer.size() > kMaxFrame) {
                fail(Codec::tr("command longer than %1 bytes").arg(kMaxFrame));
                m_buffer.clear();
                m_inFrame = false;
            }
            continue;
        }
        Command c;
        c.raw = m_buffer + '\r';
        const QByteArray f = m_buffer.mid(1);
        m_buffer.clear();
        m_inFrame = false;
        int bodyStart = 0;
        if (f.startsWith('*')) {
            c.broadcast = true;
            bodyStart = 1;
        } else {
            bodyStart = leadingDigits(f);
            if (bodyStart == 0 || bodyStart > 3) {
                c.valid = false;
                c.error = Codec::tr("command without a valid address");
            } else {
                c.address = f.left(bodyStart).toInt();
            }
        }
        c.body = f.mid(bodyStart);
        if (c.valid && c.body.isEmpty()) {
            c.valid = false;
            c.error = Codec::tr("command without a body");
        }
        out << c;
    }
    return out;
}

void CommandDecoder::reset()
{
    m_buffer.clear();
    m_inFrame = false;
}

} // namespace stepdeck::nanotec
