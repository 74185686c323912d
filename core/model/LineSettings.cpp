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

QString LineSettings::text() const
{
    const char frameParity = parity == Parity::None ? 'N' : parity == Parity::Even ? 'E' : 'O';
    return QStringLiteral("%1 %2%3%4")
        .arg(baudRate)
        .arg(dataBits)
        .arg(QLatin1Char(frameParity))
        .arg(stopBits);
}

} // namespace stepdeck
