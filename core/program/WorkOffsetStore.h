#pragma once
#include "ProgramCoordinates.h"
#include <QSettings>
#include <memory>

namespace stepdeck::program {

// The work offsets the window keeps per machine file (G54..G59 and the active system), in its
// settings: files -> axes -> offset, keyed by the file's absolute path (a path as a QSettings
// key would be split into groups at its slashes). G54's offsets keep the key they had before
// the other systems came. The window (ui::MachineWorkOffsets) writes them as the operator sets
// a zero; `stepdeck-cli run` reads them (issue 47 item 16), so a CAM file runs from the CLI in
// the coordinates the window shows.
struct StoredOffsets
{
    CoordinateSystems systems;
    int active = 0; // 0 = G54
    bool isEmpty() const;
};

class WorkOffsetStore
{
public:
    static QString settingsKey() { return QStringLiteral("machine/workOffsets"); } // G54
    // G55..G59 and the active system: files -> {"active": n, "G55": {axis: offset}, ...}.
    static QString systemsKey() { return QStringLiteral("machine/coordinateSystems"); }
    // The window's settings (QSettings' organization and application of app/gui/main.cpp), for
    // a program of another name (the CLI).
    static std::unique_ptr<QSettings> windowSettings();

    static StoredOffsets load(const QSettings& settings, const QString& absolutePath);
    static void save(QSettings& settings, const QString& absolutePath, const StoredOffsets& o);
};

} // namespace stepdeck::program
