#include "MachineTools.h"
#include <QFileInfo>
#include <QSettings>

namespace stepdeck::program {

void MachineTools::load(const QString& machineKey)
{
    // Keyed as MachineWorkOffsets keys the work origins (a connection machine's by its model).
    m_key = machineKey.isEmpty() ? QString() : QFileInfo(machineKey).absoluteFilePath();
    m_text.clear();
    m_table = {};
    if (!m_key.isEmpty()) {
        const QByteArray stored =
            QSettings().value(settingsKey()).toMap().value(m_key).toString().toUtf8();
        // A stored table that no longer reads (edited by hand) is left out, not half used.
        if (const std::optional<program::ToolTable> table =
                program::ToolTable::parse(stored, nullptr)) {
            m_text = stored;
            m_table = *table;
        }
    }
    Q_EMIT machineChanged();
    Q_EMIT changed();
}

bool MachineTools::setText(const QByteArray& text, QList<program::ProgramError>* errors)
{
    const std::optional<program::ToolTable> table = program::ToolTable::parse(text, errors);
    if (!table)
        return false;
    m_text = text;
    m_table = *table;
    if (!m_key.isEmpty()) {
        QSettings settings;
        QVariantMap tables = settings.value(settingsKey()).toMap();
        if (text.trimmed().isEmpty())
            tables.remove(m_key);
        else
            tables.insert(m_key, QString::fromUtf8(text));
        settings.setValue(settingsKey(), tables);
    }
    Q_EMIT changed();
    return true;
}

} // namespace stepdeck::program
