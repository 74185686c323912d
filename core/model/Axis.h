#pragma once
#include <QList>
#include <QMap>
#include <QString>
#include <optional>

namespace stepdeck {

// Machine axes. A model declares which of them it has (Capabilities::axes); the order here is
// the order used for per-axis values everywhere ("X,Y,Z(,U)").
enum class Axis : quint8 { X = 0, Y = 1, Z = 2, U = 3 };

QString axisName(Axis axis);
std::optional<Axis> axisFromName(QStringView name);
const QList<Axis>& allAxes();

// Signed step counts or step rates per axis; axes not present in the map are "not addressed".
using AxisVector = QMap<Axis, qint64>;
using AxisVelocities = QMap<Axis, double>;

} // namespace stepdeck
