#include "Axis.h"

namespace stepdeck {

QString axisName(Axis axis)
{
    switch (axis) {
    case Axis::X:
        return QStringLiteral("X");
    case Axis::Y:
        return QStringLiteral("Y");
    case Axis::Z:
        return QStringLiteral("Z");
    case Axis::U:
        return QStringLiteral("U");
    }
    return QStringLiteral("?");
}

std::optional<Axis> axisFromName(QStringView name)
{
    const QString upper = name.trimmed().toString().toUpper();
    for (Axis axis : allAxes()) {
        if (axisName(axis) == upper)
            return axis;
    }
    return std::nullopt;
}

const QList<Axis>& allAxes()
{
    static const QList<Axis> axes{Axis::X, Axis::Y, Axis::Z, Axis::U};
    return axes;
}

} // namespace stepdeck
