#include "MachineWorkOffsets.h"
#include "machine/Machine.h"
#include <QFileInfo>
#include <QSettings>

namespace stepdeck::ui {

MachineWorkOffsets::MachineWorkOffsets(QObject* parent) : QObject(parent) {}

void MachineWorkOffsets::load(const QString& machinePath)
{
    m_path = machinePath.isEmpty() ? QString() : QFileInfo(machinePath).absoluteFilePath();
    m_offsets.clear();
    if (!m_path.isEmpty()) {
        // One map of files -> (axis -> offset): a file path as a QSettings key would be split
        // into groups at its slashes.
        const QVariantMap files = QSettings().value(settingsKey()).toMap();
        const QVariantMap axes = files.value(m_path).toMap();
        for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
            bool ok = false;
            const double value = it.value().toDouble(&ok);
            if (ok && qIsFinite(value) && value != 0.0)
                m_offsets.insert(it.key(), value);
        }
    }
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
        m_offsets.remove(axis);
    else
        m_offsets.insert(axis, status.position);
    save();
    Q_EMIT changed();
    return true;
}

void MachineWorkOffsets::set(const QString& axis, double machinePosition)
{
    if (!qIsFinite(machinePosition) || machinePosition == 0.0)
        m_offsets.remove(axis);
    else
        m_offsets.insert(axis, machinePosition);
    save();
    Q_EMIT changed();
}

void MachineWorkOffsets::clear()
{
    m_offsets.clear();
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
    if (m_path.isEmpty())
        return;
    QSettings settings;
    QVariantMap files = settings.value(settingsKey()).toMap();
    if (m_offsets.isEmpty()) {
        files.remove(m_path);
    } else {
        QVariantMap axes;
        for (auto it = m_offsets.cbegin(); it != m_offsets.cend(); ++it)
            axes.insert(it.key(), it.value());
        files.insert(m_path, axes);
    }
    settings.setValue(settingsKey(), files);
}

} // namespace stepdeck::ui
