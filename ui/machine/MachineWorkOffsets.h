#pragma once
#include <QMap>
#include <QObject>
#include <QString>

namespace stepdeck::machine {
struct MachineAxisStatus;
}

namespace stepdeck::ui {

// The operator's work origin per machine axis (issue 19), in the axis' unit: the machine
// position at which the axis was zeroed. Work position = machine position - offset; a target
// typed in work coordinates becomes machine coordinates (+ offset) before Machine::move, so
// the machine's soft limits stay in machine coordinates. Host-side only: nothing is sent.
// Remembered per machine file (QSettings, keyed by the file's absolute path); a machine
// without a file keeps its offsets until it is closed.
class MachineWorkOffsets : public QObject
{
    Q_OBJECT
public:
    explicit MachineWorkOffsets(QObject* parent = nullptr);

    // The offsets stored for this machine file (empty path: none, nothing stored).
    void load(const QString& machinePath);
    QString machinePath() const { return m_path; }

    bool hasOffset(const QString& axis) const { return m_offsets.contains(axis); }
    bool anyOffset() const { return !m_offsets.isEmpty(); }
    const QMap<QString, double>& all() const { return m_offsets; }
    double offset(const QString& axis) const { return m_offsets.value(axis, 0.0); }

    // Sets the work origin of the axis at its machine position now. Refused (false, *refusal
    // one line) while the position is unknown or the axis moves: a work origin set there would
    // say nothing about where the machine is.
    bool zero(const QString& axis, const machine::MachineAxisStatus& status, QString* refusal);
    void clear(); // work origin = machine origin on every axis
    // Sets the work origin of the axis at this machine position (a machine without a file
    // taking over a single controller's origins); 0 removes it.
    void set(const QString& axis, double machinePosition);

    double toWork(const QString& axis, double machineUnits) const;
    double toMachine(const QString& axis, double workUnits) const;

    static QString settingsKey() { return QStringLiteral("machine/workOffsets"); }

Q_SIGNALS:
    void changed();

private:
    void save() const;

    QString m_path;
    QMap<QString, double> m_offsets; // machine axis name -> machine position of its work zero
};

} // namespace stepdeck::ui
