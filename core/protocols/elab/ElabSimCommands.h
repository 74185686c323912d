#pragma once
#include "ElabSimBoard.h"

namespace stepdeck::elab {

// The command interpreter of the simulated E-LAB board: executes one command that the notes
// of the control-character table let through (ElabSimBoard::refusedByNotes) on the board, or
// says why the board answers <NAK>. Requests (ENQ, HT, ETB, ETX, LF, SYN) and the <DC2> step
// stream are ElabSimulator's: they answer with data or not at all.
class ElabSimCommands
{
public:
    explicit ElabSimCommands(ElabSimBoard& board) : m_board(board) {}

    // True: executed, answer <ACK>. False: *why the board answers <NAK>.
    bool execute(const Command& cmd, QString* why);

private:
    bool doRamp(const Command& cmd, QString* why);
    bool doAuxiliary(const Command& cmd, QString* why); // drive power, spindle, coolant
    bool doPolarity(const Command& cmd, QString* why);
    bool doFastMove(const Command& cmd, QString* why);
    bool doFeed(const Command& cmd, QString* why);
    bool doReference(const Command& cmd, QString* why);
    bool doVelocity(const Command& cmd, QString* why);
    bool doJog(const Command& cmd, QString* why);

    ElabSimBoard& m_board;
};

} // namespace stepdeck::elab
