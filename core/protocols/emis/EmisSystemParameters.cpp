// System-parameter entries (9.14 "##" writes, 9.15 *PRSYS answers).
#include "EmisGrammar.h"

namespace stepdeck::emis {

namespace {
using Key = SystemEntry::Key;

bool parseUnsigned(const QByteArray& text, qint64* out)
{
    if (text.isEmpty() || text.size() > 18)
        return false;
    qint64 v = 0;
    for (char c : text) {
        if (c < '0' || c > '9')
            return false;
        v = v * 10 + (c - '0');
    }
    *out = v;
    return true;
}

std::optional<Axis> lowerAxis(const QByteArray& field)
{
    if (field.isEmpty() || field[0] < 'a' || field[0] > 'z')
        return std::nullopt;
    return axisFromLetter(field[0]);
}

QString malformedEntry(const QByteArray& entry)
{
    return Grammar::tr("system parameter '%1' is malformed (see the manual, 9.14)")
        .arg(QString::fromLatin1(entry));
}

// "x32,y16,z64,u1" -> values; false on a malformed field or an axis named twice.
bool perAxisValues(const QList<QByteArray>& fields, QMap<Axis, qint64>* values)
{
    if (fields.isEmpty())
        return false;
    for (const QByteArray& f : fields) {
        const auto axis = lowerAxis(f);
        qint64 v = 0;
        if (!axis || values->contains(*axis) || !parseUnsigned(f.mid(1), &v))
            return false;
        values->insert(*axis, v);
    }
    return true;
}

bool parseCurrents(const QList<QByteArray>& fields, SystemEntry* e)
{
    // "x100,0,y100,0,..." (9.14): axis with run current, then the idle current.
    if (fields.isEmpty() || fields.size() % 2 != 0)
        return false;
    for (int i = 0; i < fields.size(); i += 2) {
        const auto axis = lowerAxis(fields[i]);
        qint64 run = 0;
        qint64 idle = 0;
        if (!axis || e->values.contains(*axis) || !parseUnsigned(fields[i].mid(1), &run) ||
            !parseUnsigned(fields[i + 1], &idle))
            return false;
        e->values.insert(*axis, run);
        e->idle.insert(*axis, idle);
    }
    return true;
}

bool referenceSwitches(const QList<QByteArray>& fields, SystemEntry* e)
{
    if (fields.isEmpty())
        return false;
    for (const QByteArray& f : fields) {
        const auto axis = lowerAxis(f);
        const QByteArray type = f.mid(1).toUpper();
        if (!axis || e->normallyClosed.contains(*axis) || (type != "NO" && type != "NC"))
            return false;
        e->normallyClosed.insert(*axis, type == "NC");
    }
    return true;
}

QByteArray perAxisText(const QMap<Axis, qint64>& values)
{
    QByteArray out;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        out += ',' + QByteArray(1, axisLetter(it.key())) + QByteArray::number(it.value());
    return out;
}
} // namespace

int SystemEntry::motorCount() const
{
    switch (key) {
    case Key::ReferenceSwitch:
        return int(normallyClosed.size());
    case Key::Ramp:
    case Key::SmcFlex:
        return 4;
    default:
        return int(values.size());
    }
}

std::optional<SystemEntry> parseSystemEntry(const QByteArray& entry, QString* error)
{
    QList<QByteArray> fields = entry.split(',');
    const QByteArray key = fields.takeFirst();
    SystemEntry e;
    bool ok = false;
    if (key == "D") {
        e.key = Key::StepResolution;
        ok = perAxisValues(fields, &e.values);
    } else if (key == "c") {
        e.key = Key::Currents;
        ok = parseCurrents(fields, &e);
    } else if (key == "REFSW") {
        e.key = Key::ReferenceSwitch;
        ok = referenceSwitches(fields, &e);
    } else if (key == "S" && fields.size() == 3 && !lowerAxis(fields[0])) {
        // "##S,200,1800,100": SMCflex compatibility (9.14); StepDeck never writes it.
        e.key = Key::SmcFlex;
        ok = parseUnsigned(fields[0], &e.flexStart) && parseUnsigned(fields[1], &e.flexWork) &&
             parseUnsigned(fields[2], &e.flexRamp);
    } else if (key == "S" || key == "E" || key == "E9") {
        e.key = key == "S" ? Key::StartSpeed : (key == "E" ? Key::WorkSpeed : Key::ReferenceSpeed);
        ok = perAxisValues(fields, &e.values);
    } else if (key == "R") {
        e.key = Key::Ramp;
        ok = fields.size() == 1 && parseUnsigned(fields[0], &e.ramp);
    } else {
        if (error) {
            *error = Grammar::tr("unknown system parameter '%1' (9.14 knows D, c, REFSW, S, E, "
                                 "E9, R)")
                         .arg(QString::fromLatin1(key));
        }
        return std::nullopt;
    }
    if (!ok) {
        if (error)
            *error = malformedEntry(entry);
        return std::nullopt;
    }
    return e;
}

QByteArray formatSystemEntry(const SystemEntry& e)
{
    switch (e.key) {
    case Key::StepResolution:
        return "D" + perAxisText(e.values);
    case Key::StartSpeed:
        return "S" + perAxisText(e.values);
    case Key::WorkSpeed:
        return "E" + perAxisText(e.values);
    case Key::ReferenceSpeed:
        return "E9" + perAxisText(e.values);
    case Key::Ramp:
        return "R," + QByteArray::number(e.ramp);
    case Key::SmcFlex:
        return "S," + QByteArray::number(e.flexStart) + ',' + QByteArray::number(e.flexWork) + ',' +
               QByteArray::number(e.flexRamp);
    case Key::Currents: {
        QByteArray out = "c";
        for (auto it = e.values.cbegin(); it != e.values.cend(); ++it) {
            out += ',' + QByteArray(1, axisLetter(it.key())) + QByteArray::number(it.value()) +
                   ',' + QByteArray::number(e.idle.value(it.key()));
        }
        return out;
    }
    case Key::ReferenceSwitch: {
        QByteArray out = "REFSW";
        for (auto it = e.normallyClosed.cbegin(); it != e.normallyClosed.cend(); ++it)
            out += ',' + QByteArray(1, axisLetter(it.key())) + (it.value() ? "NC" : "NO");
        return out;
    }
    }
    return {};
}

const SystemEntry* SystemParameters::find(SystemEntry::Key key) const
{
    for (const SystemEntry& e : entries) {
        if (e.key == key)
            return &e;
    }
    return nullptr;
}

void SystemParameters::store(const SystemEntry& entry)
{
    for (SystemEntry& e : entries) {
        if (e.key != entry.key)
            continue;
        e.values.insert(entry.values);
        e.idle.insert(entry.idle);
        e.normallyClosed.insert(entry.normallyClosed);
        e.ramp = entry.ramp;
        e.flexStart = entry.flexStart;
        e.flexWork = entry.flexWork;
        e.flexRamp = entry.flexRamp;
        return;
    }
    entries << entry;
}

SystemParameters parseSystemParameters(const QByteArray& text)
{
    QByteArray payload = payloadAfterEcho(text, "*PRSYS");
    if (payload.startsWith(':'))
        payload = payload.mid(1);
    for (char& c : payload) {
        if (c == ';' || c == '\r' || c == '\n' || c == '\t')
            c = ' ';
    }
    SystemParameters out;
    for (const QByteArray& token : payload.split(' ')) {
        for (const QByteArray& piece : token.split('#')) {
            if (piece.isEmpty())
                continue; // "##" splits into empty pieces
            if (const auto entry = parseSystemEntry(piece, nullptr))
                out.store(*entry);
            else
                out.unparsed << piece;
        }
    }
    return out;
}

QByteArray formatSystemParameters(const QList<SystemEntry>& entries)
{
    QByteArray out = "*PRSYS:";
    for (int i = 0; i < entries.size(); ++i)
        out += (i ? "\r\n##" : "##") + formatSystemEntry(entries[i]);
    return out;
}

} // namespace stepdeck::emis
