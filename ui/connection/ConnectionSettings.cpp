#include "ConnectionSettings.h"
#include <QSettings>

namespace stepdeck::ui::connectionsettings {

namespace {
const QString kRecent = QStringLiteral("connection/recentPorts");
const QString kAutoReconnect = QStringLiteral("connection/autoReconnect");

QString resetLineKey(const QString& modelId)
{
    return QStringLiteral("connection/%1/resetLine").arg(modelId);
}
} // namespace

QStringList recentPorts()
{
    QStringList ports = QSettings().value(kRecent).toStringList();
    ports.removeAll(QString());
    ports.removeDuplicates();
    return ports.mid(0, kMaxRecentPorts);
}

void addRecentPort(const QString& port)
{
    if (port.trimmed().isEmpty())
        return;
    QStringList ports = recentPorts();
    ports.removeAll(port);
    ports.prepend(port);
    QSettings().setValue(kRecent, ports.mid(0, kMaxRecentPorts));
}

LineSettings::ResetLine resetLine(const QString& modelId)
{
    const QString name = QSettings().value(resetLineKey(modelId)).toString();
    return resetLineFromName(name).value_or(LineSettings::ResetLine::Rts);
}

void setResetLine(const QString& modelId, LineSettings::ResetLine line)
{
    QSettings().setValue(resetLineKey(modelId), resetLineName(line));
}

bool autoReconnect()
{
    return QSettings().value(kAutoReconnect, true).toBool();
}

void setAutoReconnect(bool on)
{
    QSettings().setValue(kAutoReconnect, on);
}

} // namespace stepdeck::ui::connectionsettings
