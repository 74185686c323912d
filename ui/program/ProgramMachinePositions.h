#pragma once
#include <QCoreApplication>
#include <QMap>
#include <QString>
#include <optional>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

// Where a machine's axes stand, as the Program page needs it (issue 20): the known positions
// (read back or referenced; unknown ones left out) for the path's marker, a text naming each
// axis for the "Run from line" confirmation, and a signature that changes when the machine
// came to rest somewhere new (the check follows the positions).
class ProgramMachinePositions
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::ui::ProgramMachinePositions)
public:
    static QMap<QString, double> known(const machine::Machine& machine);
    // "X 10.000 mm, Y 5.000 mm, A unknown", in the machine's axis order.
    static QString text(const machine::Machine& machine);
    // Every axis' count and whether it is known; nullopt while any axis moves.
    static std::optional<QString> restingSignature(const machine::Machine& machine);
};

} // namespace stepdeck::ui
