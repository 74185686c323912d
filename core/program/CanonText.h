#pragma once
#include "machine/MachineDescription.h"
#include "motion/MotionCommand.h"
#include <QStringList>

namespace stepdeck::program {

// The motion commands as text in the style of LinuxCNC's standalone interpreter `rs274`
// (issue 49 item 6; docs/cli.md "--canon"), so that StepDeck's reading of a program can be held
// against LinuxCNC's line by line: one call per line, numbered, with the program line it comes
// from (`N00012`), positions in program coordinates and units (the frame calls before them say
// which: USE_LENGTH_UNITS, SET_G5X_OFFSET, SET_G92_OFFSET, USE_TOOL_LENGTH_OFFSET), four
// decimals, "?" for a position that is not known.
//
// Where StepDeck differs from rs274's output, by design: the positions are the machine's axes
// in its file's order (rs274 always prints X Y Z A B C, and U V W where configured); G28 is a
// reference run here (REFERENCE_AXES, StepDeck's own call); the program end is preceded by the
// spindle and coolant off the run sends.
class CanonText
{
public:
    explicit CanonText(const machine::MachineDescription& d);
    // The lines of one command (a frame command of which nothing changed: none).
    QStringList lines(const motion::MotionCommand& command);

private:
    QStringList calls(const motion::MotionCommand& command);
    QString point(const motion::MachinePoint& end) const;
    QString arc(const motion::ArcFeed& arc) const;
    QStringList offsets(const motion::Offsets& o);
    // A machine position of axis i in program terms: less the frame's offsets, in the
    // program's unit.
    QString programValue(int i, std::optional<double> machine) const;
    QString programLength(int i, double length) const; // an offset or length, no frame
    double perProgramUnit(int i) const;

    const machine::MachineDescription& m_d;
    int m_sequence = 0;
    bool m_inches = false;
    bool m_inverseTime = false;
    motion::Offsets m_frame;
};

} // namespace stepdeck::program
