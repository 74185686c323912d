#pragma once
#include "ToolTable.h"
#include <QObject>

namespace stepdeck::program {

// A machine's tool table (issue 29, docs/programs.md "Tools"): what G43 offsets Z by and what
// M6 asks the operator to load, kept as LinuxCNC's tool.tbl text per machine file (QSettings,
// keyed by the file's absolute path; a connection machine by its model, as its work offsets),
// so a technician can paste the table of a LinuxCNC machine. Host-side only: nothing is sent.
class MachineTools : public QObject
{
    Q_OBJECT
public:
    explicit MachineTools(QObject* parent = nullptr) : QObject(parent) {}

    void load(const QString& machineKey); // empty: none, nothing stored
    const program::ToolTable& table() const { return m_table; }
    QByteArray text() const { return m_text; }
    // The text as the table, stored; false with *errors (nothing changes) when it is not one.
    bool setText(const QByteArray& text, QList<program::ProgramError>* errors);

    static QString settingsKey() { return QStringLiteral("machine/toolTables"); }

Q_SIGNALS:
    void changed();
    void machineChanged(); // load(): another machine's table (changed() follows)

private:
    QString m_key;
    QByteArray m_text;
    program::ToolTable m_table;
};

} // namespace stepdeck::program
