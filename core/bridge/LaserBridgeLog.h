#pragma once
#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace stepdeck::bridge {

// One line of the laser bridge's log: a laser frame in or out, an ignored frame, a note or an
// error. The CLI prints it (text or JSON), the bridge page lists it and shows errors at once.
struct LaserBridgeLogEntry
{
    enum class Kind { FromLaser, ToLaser, Ignored, Note, Error };
    QDateTime time;
    Kind kind = Kind::Note;
    QByteArray frame; // without CR; empty for notes
    QString text;
};

// "HH:mm:ss.zzz  kind  frame  text" on one line.
QString formatLaserBridgeLogEntry(const LaserBridgeLogEntry& entry);

} // namespace stepdeck::bridge
