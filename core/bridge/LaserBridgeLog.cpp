#include "LaserBridgeLog.h"
#include "model/ModelPresentation.h"
#include <QCoreApplication>

namespace stepdeck::bridge {

namespace {
// The words keep the translation context of the class they came from.
QString kindText(LaserBridgeLogEntry::Kind kind)
{
    switch (kind) {
    case LaserBridgeLogEntry::Kind::FromLaser:
        return QCoreApplication::translate("stepdeck::bridge::LaserBridge", "laser  ->");
    case LaserBridgeLogEntry::Kind::ToLaser:
        return QCoreApplication::translate("stepdeck::bridge::LaserBridge", "laser <- ");
    case LaserBridgeLogEntry::Kind::Ignored:
        return QCoreApplication::translate("stepdeck::bridge::LaserBridge", "ignored  ");
    case LaserBridgeLogEntry::Kind::Note:
        return QCoreApplication::translate("stepdeck::bridge::LaserBridge", "note     ");
    case LaserBridgeLogEntry::Kind::Error:
        return QCoreApplication::translate("stepdeck::bridge::LaserBridge", "ERROR    ");
    }
    return {};
}
} // namespace

QString formatLaserBridgeLogEntry(const LaserBridgeLogEntry& entry)
{
    const QString frame = entry.frame.isEmpty() ? QString() : genericFormatTraffic(entry.frame);
    return QStringLiteral("%1  %2  %3  %4")
        .arg(entry.time.toString(QStringLiteral("HH:mm:ss.zzz")))
        .arg(kindText(entry.kind))
        .arg(frame, -8)
        .arg(entry.text);
}

} // namespace stepdeck::bridge
