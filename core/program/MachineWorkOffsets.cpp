#include "MachineWorkOffsets.h"
#include "WorkOffsetStore.h"
#include "machine/Machine.h"
#include <QFileInfo>
#include <QSettings>

namespace stepdeck::program {

MachineWorkOffsets::MachineWorkOffsets(QObject* parent) : QObject(parent) {}

void MachineWorkOffsets::load(const QString& machinePath)
{
    m_path = machinePath.isEmpty() ? QString() : QFileInfo(machinePath).absoluteFilePath();
    const program::StoredOffsets stored = program::WorkOffsetStore::load(QSettings(), m_path);
    m_systems = stored.systems;
    m_active = stored.active;
    Q_EMIT changed();
}

void MachineWorkOffsets::setActive(int system)
{
    if (system < 0 || system >= program::kCoordinateSystems || system == m_active)
        return;
    m_active = system;
    save();
    Q_EMIT changed();
}

void MachineWorkOffsets::setSystem(int system, const QMap<QString, double>& offsets)
{
    if (system < 0 || system >= program::kCoordinateSystems)
        return;
    QMap<QString, double> kept;
    for (auto it = offsets.cbegin(); it != offsets.cend(); ++it)
        if (qIsFinite(it.value()) && it.value() != 0.0)
            kept.insert(it.key(), it.value());
    m_systems[size_t(system)] = kept;
    save();
    Q_EMIT changed();
}

bool MachineWorkOffsets::zero(const QString& axis, const machine::MachineAxisStatus& status,
                              QString* refusal)
{
    if (status.known == machine::PositionKnowledge::Unknown) {
        if (refusal)
            *refusal =
                tr("Zero %1 refused: its position is unknown; reference it first.").arg(axis);
        return false;
    }
    if (status.moving) {
        if (refusal)
            *refusal = tr("Zero %1 refused: the axis is moving.").arg(axis);
        return false;
    }
    if (status.position == 0.0)
        activeOffsets().remove(axis);
    else
        activeOffsets().insert(axis, status.position);
    save();
    Q_EMIT changed();
    return true;
}

void MachineWorkOffsets::set(const QString& axis, double machinePosition)
{
    if (!qIsFinite(machinePosition) || machinePosition == 0.0)
        activeOffsets().remove(axis);
    else
        activeOffsets().insert(axis, machinePosition);
    save();
    Q_EMIT changed();
}

void MachineWorkOffsets::clear()
{
    activeOffsets().clear();
    save();
    Q_EMIT changed();
}

double MachineWorkOffsets::toWork(const QString& axis, double machineUnits) const
{
    return machineUnits - offset(axis);
}

double MachineWorkOffsets::toMachine(const QString& axis, double workUnits) const
{
    return workUnits + offset(axis);
}

void MachineWorkOffsets::save() const
{
    QSettings settings;
    program::WorkOffsetStore::save(settings, m_path, program::StoredOffsets{m_systems, m_active});
}

} // namespace stepdeck::program
