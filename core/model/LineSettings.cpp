#include "LineSettings.h"

namespace stepdeck {

std::optional<LineSettings::ResetLine> resetLineFromName(const QString& name)
{
    if (name.compare(QLatin1String("rts"), Qt::CaseInsensitive) == 0)
        return LineSettings::ResetLine::Rts;
    if (name.compare(QLatin1String("dtr"), Qt::CaseInsensitive) == 0)
        return LineSettings::ResetLine::Dtr;
    return std::nullopt;
}

QString resetLineName(LineSettings::ResetLine line)
{
    return line == LineSettings::ResetLine::Dtr ? QStringLiteral("dtr") : QStringLiteral("rts");
}

} // namespace stepdeck
