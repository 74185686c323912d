#include "AxisNames.h"
#include "model/NumberParsing.h"
#include <QSet>
#include <limits>

namespace stepdeck {

bool AxisNames::isValidName(QStringView name)
{
    // One letter is X, Y, Z or U: "A=1" would read as the machine's axis A (or a typo).
    if (name.size() == 1)
        return axisFromName(name).has_value();
    if (name.isEmpty() || name.size() > kMaxNameLength || !name.front().isLetter())
        return false;
    for (QChar c : name) {
        if (!(c.isLetterOrNumber() || c == QLatin1Char('_')) || c.unicode() > 127)
            return false;
    }
    return true;
}

QString AxisNames::invalidNameText(const QString& name)
{
    return tr("'%1' is not an axis name (X, Y, Z, U, or a letter and then letters, digits or _, "
              "2 to %2 characters)")
        .arg(name)
        .arg(kMaxNameLength);
}

QString AxisNames::name(Axis axis) const
{
    return m_names.value(axis, axisName(axis));
}

std::optional<Axis> AxisNames::find(QStringView name) const
{
    for (auto it = m_names.cbegin(); it != m_names.cend(); ++it) {
        if (name.compare(it.value(), Qt::CaseInsensitive) == 0)
            return it.key();
    }
    return axisFromName(name); // reserved for its axis, so never another axis' name
}

bool AxisNames::setName(Axis axis, const QString& name, QString* error)
{
    if (!isValidName(name)) {
        *error = invalidNameText(name);
        return false;
    }
    if (const std::optional<Axis> byDefault = axisFromName(name)) {
        if (*byDefault != axis) {
            *error = tr("%1 is the name of another axis").arg(axisName(*byDefault));
            return false;
        }
        m_names.remove(axis);
        return true;
    }
    for (auto it = m_names.cbegin(); it != m_names.cend(); ++it) {
        if (it.key() != axis && name.compare(it.value(), Qt::CaseInsensitive) == 0) {
            *error = tr("%1 names two axes").arg(name);
            return false;
        }
    }
    m_names.insert(axis, name);
    return true;
}

bool assignBusAxes(const QList<NamedAddress>& list, QMap<Axis, int>* addresses, AxisNames* names,
                   QString* error)
{
    QMap<Axis, int> outAddresses;
    AxisNames outNames;
    QSet<QString> seen;
    for (const NamedAddress& e : list) {
        if (seen.contains(e.name.toUpper())) {
            *error = AxisNames::tr("%1 is given twice").arg(e.name);
            return false;
        }
        seen.insert(e.name.toUpper());
        if (const std::optional<Axis> own = axisFromName(e.name))
            outAddresses.insert(*own, e.address);
    }
    int next = 0;
    for (const NamedAddress& e : list) {
        if (axisFromName(e.name))
            continue;
        while (outAddresses.contains(Axis::at(next)))
            ++next;
        const std::optional<Axis> axis = Axis::fromIndex(next);
        if (!axis) {
            *error = AxisNames::tr("more than %1 axes").arg(Axis::kMaxCount);
            return false;
        }
        if (!outNames.setName(*axis, e.name, error))
            return false;
        outAddresses.insert(*axis, e.address);
    }
    *addresses = outAddresses;
    *names = outNames;
    return true;
}

bool parseNamedAddresses(const QString& text, QList<NamedAddress>* out, QString* error)
{
    QList<NamedAddress> result;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        if (part.trimmed().isEmpty())
            continue;
        const int eq = part.indexOf(QLatin1Char('='));
        const QString name = part.left(eq).trimmed();
        if (eq <= 0) {
            *error = AxisNames::tr("expected NAME=ADDRESS (e.g. feeder=5), got '%1'").arg(part);
            return false;
        }
        if (!AxisNames::isValidName(name)) {
            *error = AxisNames::invalidNameText(name);
            return false;
        }
        qint64 address = 0;
        if (numbers::parseInteger(QStringView(part).mid(eq + 1).trimmed(), 0,
                                  std::numeric_limits<int>::max(), &address) != NumberError::None) {
            *error =
                AxisNames::tr("%1: '%2' is not a whole bus address").arg(name, part.mid(eq + 1));
            return false;
        }
        result << NamedAddress{name, int(address)};
    }
    if (result.isEmpty()) {
        *error = AxisNames::tr("no axis given (e.g. X=1,Y=2 or feeder=5,gate=6)");
        return false;
    }
    *out = result;
    return true;
}

QList<NamedAddress> namedAddresses(const QMap<Axis, int>& addresses, const AxisNames& names)
{
    QList<NamedAddress> list;
    for (auto it = addresses.cbegin(); it != addresses.cend(); ++it)
        list << NamedAddress{names.name(it.key()), it.value()};
    return list;
}

} // namespace stepdeck
