#include "ProgramMachinePositions.h"
#include "machine/Machine.h"

namespace stepdeck::ui {

QMap<QString, double> ProgramMachinePositions::known(const machine::Machine& machine)
{
    QMap<QString, double> out;
    for (const machine::MachineAxis& a : machine.description().axes) {
        const machine::MachineAxisStatus s = machine.axisStatus(a);
        if (s.known != machine::PositionKnowledge::Unknown)
            out.insert(a.name, s.position);
    }
    return out;
}

QString ProgramMachinePositions::text(const machine::Machine& machine)
{
    const QMap<QString, double> positions = known(machine);
    QStringList where;
    for (const machine::MachineAxis& a : machine.description().axes) {
        where << (positions.contains(a.name) ? QStringLiteral("%1 %2 %3")
                                                   .arg(a.name)
                                                   .arg(positions.value(a.name), 0, 'f', 3)
                                                   .arg(machine::unitKey(a.unit))
                                             : tr("%1 unknown").arg(a.name));
    }
    return where.join(QStringLiteral(", "));
}

std::optional<QString> ProgramMachinePositions::restingSignature(const machine::Machine& machine)
{
    QString out;
    for (const machine::MachineAxis& a : machine.description().axes) {
        const machine::MachineAxisStatus s = machine.axisStatus(a);
        if (s.moving)
            return std::nullopt;
        out += QStringLiteral("%1=%2%3;")
                   .arg(a.name)
                   .arg(s.steps)
                   .arg(s.known == machine::PositionKnowledge::Unknown ? QStringLiteral("?")
                                                                       : QString());
    }
    return out;
}

} // namespace stepdeck::ui
