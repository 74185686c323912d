#include "MachineWorkOffsets.h"
#include "machine/Machine.h"
#include <QFileInfo>
#include <QSettings>

namespace stepdeck::ui {

MachineWorkOffsets::MachineWorkOffsets(QObject* parent) : QObject(parent) {}

namespace {
QMap<QString, double> offsetsOf(const QVariantMap& axes)
{
    QMap<QString, double> out;
    for (auto it = axes.cbegin(); it != axes.cend(); ++it) {
        bool ok = false;
        const double value = it.value().toDouble(&ok);
        if (ok && qIsFinite(value) && value != 0.0)
            out.insert(it.key(), value);
    }
    return out;
}

QVariantMap variantOf(const QMap<QString, double>& offsets)
{
    QVariantMap axes;
    for (auto it = offsets.cbegin(); it != offsets.cend(); ++it)
        axes.insert(it.key(), it.value());
    return axes;
}
} // namespace

void MachineWorkOffsets::load(const QString& machinePath)
{
    m_path = machinePath.isEmpty() ? QString() : QFileInfo(machinePath).absoluteFilePath();
    m_systems = {};
    m_active = 0;
    if (!m_path.isEmpty()) {
        // One map of files -> (axis -> offset): a file path as a QSettings key would be split
        // into groups at its slashes.
        const QSettings settings;
        m_systems[0] = offsetsOf(settings.value(settingsKey()).toMap().value(m_path).toMap());
        const QVariantMap more = settings.value(systemsKey()).toMap().value(m_path).toMap();
        for (int i = 1; i < program::kCoordinateSystems; ++i)
            m_systems[size_t(i)] = offsetsOf(more.value(program::coordinateSystemWord(i)).toMap());
        const int active = more.value(QStringLiteral("active"), 0).toInt();
        m_active = active >= 0 && active < program::kCoordinateSystems ? active : 0;
    }
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
    if (m_path.isEmpty())
        return;
    QSettings settings;
    QVariantMap files = settings.value(settingsKey()).toMap();
    if (m_systems[0].isEmpty())
        files.remove(m_path);
    else
        files.insert(m_path, variantOf(m_systems[0]));
    settings.setValue(settingsKey(), files);
    QVariantMap more;
    for (int i = 1; i < program::kCoordinateSystems; ++i)
        if (!m_systems[size_t(i)].isEmpty())
            more.insert(program::coordinateSystemWord(i), variantOf(m_systems[size_t(i)]));
    if (m_active != 0)
        more.insert(QStringLiteral("active"), m_active);
    QVariantMap systems = settings.value(systemsKey()).toMap();
    if (more.isEmpty())
        systems.remove(m_path);
    else
        systems.insert(m_path, more);
    settings.setValue(systemsKey(), systems);
}

} // namespace stepdeck::ui
