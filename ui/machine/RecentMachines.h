#pragma once
#include <QStringList>

namespace stepdeck::ui::recentmachines {

// The machine files used last (QSettings "machines/recent"), most recent first, remembered
// like the connection bar's recent ports (connection/ConnectionSettings.h).
constexpr int kMaxRecentMachines = 8;

QStringList list();
// Moves path (made absolute) to the front, adding it if new; drops the oldest beyond the cap.
void add(const QString& path);
void remove(const QString& path);
void clear();

} // namespace stepdeck::ui::recentmachines
