#pragma once
#include "model/LineSettings.h"
#include <QStringList>

namespace stepdeck::ui::connectionsettings {

// What the connection bar remembers between runs (QSettings "connection/..."): the last
// model, port and poll interval, the recently used ports, the reset line per model and the
// auto-reconnect option (issues 7 and 10).

// At most this many recent ports are kept, most recent first.
constexpr int kMaxRecentPorts = 8;

QStringList recentPorts();
// Moves port to the front of the list (adds it if new) and drops the oldest beyond the limit.
void addRecentPort(const QString& port);

// The modem line wired to the board's reset input, per model (RTS unless chosen otherwise).
LineSettings::ResetLine resetLine(const QString& modelId);
void setResetLine(const QString& modelId, LineSettings::ResetLine line);

// Reconnect when the same USB device (VID:PID + serial number) comes back; default on.
bool autoReconnect();
void setAutoReconnect(bool on);

} // namespace stepdeck::ui::connectionsettings
