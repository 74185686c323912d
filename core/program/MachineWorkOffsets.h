#pragma once
#include "ProgramCoordinates.h"
#include "WorkOffsetStore.h"
#include <QMap>
#include <QObject>
#include <QString>

namespace stepdeck::machine {
struct MachineAxisStatus;
}

namespace stepdeck::program {

// The operator's work origin per machine axis (issue 19), in the axis' unit: the machine
// position at which the axis was zeroed. Work position = machine position - offset; a target
// typed in work coordinates becomes machine coordinates (+ offset) before Machine::move, so
// the machine's soft limits stay in machine coordinates. Host-side only: nothing is sent.
// Remembered per machine file (QSettings, keyed by the file's absolute path); a machine
// without a file keeps its offsets until it is closed.
// Issue 29: one such origin per coordinate system G54..G59 (program::CoordinateSystems), one of
// them active: "Zero", the display and Go to use the active one, a program without G54..G59
// runs in it, and a program's G10 L2/L20 sets any (setSystem). G54's origins keep the storage
// they had before the other systems came.
class MachineWorkOffsets : public QObject
{
    Q_OBJECT
public:
    explicit MachineWorkOffsets(QObject* parent = nullptr);

    // The offsets stored for this machine file (empty path: none, nothing stored).
    void load(const QString& machinePath);
    QString machinePath() const { return m_path; }

    // The active system's.
    bool hasOffset(const QString& axis) const { return all().contains(axis); }
    bool anyOffset() const { return !all().isEmpty(); }
    const QMap<QString, double>& all() const { return m_systems[size_t(m_active)]; }
    double offset(const QString& axis) const { return all().value(axis, 0.0); }

    int active() const { return m_active; } // 0 = G54
    void setActive(int system);
    const program::CoordinateSystems& systems() const { return m_systems; }
    // A whole system's origins (a program's G10 L2/L20); zeros are left out.
    void setSystem(int system, const QMap<QString, double>& offsets);

    // Sets the work origin of the axis at its machine position now. Refused (false, *refusal
    // one line) while the position is unknown or the axis moves: a work origin set there would
    // say nothing about where the machine is.
    bool zero(const QString& axis, const machine::MachineAxisStatus& status, QString* refusal);
    void clear(); // work origin = machine origin on every axis (of the active system)
    // Sets the work origin of the axis at this machine position (a machine without a file
    // taking over a single controller's origins); 0 removes it.
    void set(const QString& axis, double machinePosition);

    double toWork(const QString& axis, double machineUnits) const;
    double toMachine(const QString& axis, double workUnits) const;

    // Where they are kept (program::WorkOffsetStore, which the CLI reads too).
    static QString settingsKey() { return program::WorkOffsetStore::settingsKey(); }
    static QString systemsKey() { return program::WorkOffsetStore::systemsKey(); }

Q_SIGNALS:
    void changed();

private:
    void save() const;

    QString m_path;
    QMap<QString, double>& activeOffsets() { return m_systems[size_t(m_active)]; }

    // Per system: machine axis name -> machine position of its work zero.
    program::CoordinateSystems m_systems;
    int m_active = 0;
};

} // namespace stepdeck::program
