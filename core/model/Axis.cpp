#include "Axis.h"
#include <algorithm>

namespace stepdeck {

namespace {
const char kLetters[] = "XYZU";
constexpr QLatin1StringView kPrefix("axis");
} // namespace

QString axisName(Axis axis)
{
    if (axis.index() < 4)
        return QString(QLatin1Char(kLetters[axis.index()]));
    return kPrefix + QString::number(axis.index() + 1);
}

std::optional<Axis> axisFromName(QStringView name)
{
    const QString upper = name.trimmed().toString().toUpper();
    if (upper.size() == 1) {
        const int letter = QByteArray(kLetters).indexOf(upper.at(0).toLatin1());
        return letter >= 0 ? Axis::fromIndex(letter) : std::nullopt;
    }
    if (!upper.startsWith(QString(kPrefix).toUpper()))
        return std::nullopt;
    const QStringView digits = QStringView(upper).mid(kPrefix.size());
    if (digits.isEmpty() || digits.startsWith(QLatin1Char('0')) ||
        !std::all_of(digits.cbegin(), digits.cend(), [](QChar c) { return c.isDigit(); }))
        return std::nullopt;
    bool ok = false;
    const int number = digits.toInt(&ok);
    // axis1..axis4 have letters; only the letters name them.
    if (!ok || number <= 4)
        return std::nullopt;
    return Axis::fromIndex(number - 1);
}

const QList<Axis>& letterAxes()
{
    static const QList<Axis> axes{Axis::X, Axis::Y, Axis::Z, Axis::U};
    return axes;
}

} // namespace stepdeck
