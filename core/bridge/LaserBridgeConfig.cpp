#include "LaserBridgeConfig.h"
#include "model/NumberParsing.h"
#include "protocols/laser/LaserCodec.h"
#include <QtMath>

namespace stepdeck::bridge {

namespace {
// "A=B" pairs separated by commas; false on anything else.
bool splitPairs(const QString& text, QList<QPair<QString, QString>>* pairs)
{
    const QStringList parts = text.split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (parts.isEmpty())
        return false;
    for (const QString& part : parts) {
        const int eq = part.indexOf(QLatin1Char('='));
        if (eq <= 0 || eq == part.size() - 1)
            return false;
        pairs->append({part.left(eq).trimmed(), part.mid(eq + 1).trimmed()});
    }
    return true;
}
} // namespace

bool LaserBridgeConfig::parseMap(const QString& text, QMap<Axis, Axis>* map, QString* error)
{
    QList<QPair<QString, QString>> pairs;
    QMap<Axis, Axis> out;
    if (!splitPairs(text, &pairs)) {
        *error = tr("--map expects LASER_AXIS=AXIS pairs such as 1=X,2=Y,3=Z, got '%1'").arg(text);
        return false;
    }
    for (const auto& [laserText, axisText] : pairs) {
        int number = 0;
        const bool ok =
            numbers::parseInt(laserText, 1, laser::kAxisCount, &number) == NumberError::None;
        const std::optional<Axis> laserAxis = laser::axisFromNumber(ok ? number : 0);
        const std::optional<Axis> axis = axisFromName(axisText);
        if (!laserAxis.has_value() || !axis.has_value()) {
            *error = tr("--map: '%1=%2' is not LASER_AXIS=AXIS (laser axes 1, 2, 3; axes X, Y, "
                        "Z, U)")
                         .arg(laserText, axisText);
            return false;
        }
        const Axis from = laserAxis.value();
        if (out.contains(from)) {
            *error = tr("--map: laser axis %1 is mapped twice").arg(number);
            return false;
        }
        out.insert(from, axis.value());
    }
    *map = out;
    return true;
}

bool LaserBridgeConfig::parseScale(const QString& text, double* scale, QString* error)
{
    double value = 0;
    const bool ok = numbers::parseReal(text, &value) == NumberError::None;
    if (!ok || !qIsFinite(value) || value <= 0 || value > kMaxScale) {
        *error = tr("--scale expects steps per laser unit, a number above 0 and at most %1, got "
                    "'%2'")
                     .arg(kMaxScale, 0, 'g', 7)
                     .arg(text);
        return false;
    }
    *scale = value;
    return true;
}

bool LaserBridgeConfig::parseHome(const QString& text, QMap<Axis, int>* directions, QString* error)
{
    QList<QPair<QString, QString>> pairs;
    QMap<Axis, int> out;
    bool ok = splitPairs(text, &pairs);
    for (const auto& [axisText, dirText] : pairs) {
        const std::optional<Axis> axis = axisFromName(axisText);
        int direction = 0;
        const bool numberOk = numbers::parseInt(dirText, -1, 1, &direction) == NumberError::None;
        if (!axis || !numberOk || direction == 0 || out.contains(*axis)) {
            ok = false;
            break;
        }
        out.insert(*axis, direction);
    }
    if (!ok) {
        *error =
            tr("--home expects AXIS=-1 or AXIS=1 per axis, e.g. X=-1,Y=-1,Z=1, got '%1'").arg(text);
        return false;
    }
    *directions = out;
    return true;
}

bool LaserBridgeConfig::parseDoorInput(const QString& text, int* input, QString* error)
{
    int value = 0;
    const bool ok = numbers::parseInt(text, 1, 64, &value) == NumberError::None;
    if (!ok) {
        *error = tr("--door-input expects an input number from 1 to 64, got '%1'").arg(text);
        return false;
    }
    *input = value;
    return true;
}

QString LaserBridgeConfig::validate(const Capabilities& controller) const
{
    if (axisMap.isEmpty())
        return tr("the axis map is empty: map at least one laser axis");
    QList<Axis> used;
    for (auto it = axisMap.cbegin(); it != axisMap.cend(); ++it) {
        if (!controller.axes.contains(it.value()))
            return tr("the controller has no axis %1 (laser axis %2)")
                .arg(axisName(it.value()))
                .arg(laser::axisNumber(it.key()));
        if (used.contains(it.value()))
            return tr("axis %1 is mapped to two laser axes").arg(axisName(it.value()));
        used << it.value();
    }
    if (!homeDirections.isEmpty() && !controller.referenceDirection)
        return tr("--home: this controller chooses the direction of its reference runs itself; "
                  "leave --home out");
    for (auto it = homeDirections.cbegin(); it != homeDirections.cend(); ++it) {
        if (!used.contains(it.key()))
            return tr("--home names axis %1, which no laser axis is mapped to")
                .arg(axisName(it.key()));
    }
    if (!qIsFinite(scale) || scale <= 0 || scale > kMaxScale)
        return tr("the scale must be above 0 and at most %1 steps per laser unit")
            .arg(kMaxScale, 0, 'g', 7);
    return {};
}

QString LaserBridgeConfig::mapText() const
{
    QStringList parts;
    for (auto it = axisMap.cbegin(); it != axisMap.cend(); ++it)
        parts << QStringLiteral("%1=%2").arg(laser::axisNumber(it.key())).arg(axisName(it.value()));
    return parts.join(QLatin1Char(','));
}

} // namespace stepdeck::bridge
