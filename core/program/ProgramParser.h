#pragma once
#include "ProgramBlock.h"
#include "ProgramLexer.h"
#include "ProgramLine.h"
#include <QByteArray>
#include <QCoreApplication>

namespace stepdeck::program {

// Reads a motion program (issue 20, docs/programs.md): UTF-8, one block per line, the G-code
// subset G0 G1 G4 G20 G21 G28 G90 G91, M0 M2 M30 M3 M5 M7 M8 M9 M64 M65 M66, F S P L Q, N numbers,
// O<n> repeat/endrepeat and comments. Streaming: bytes may arrive in any chunks; lines are
// bounded (kMaxLineLength), so is the program (kMaxLines) and the error list (kMaxErrors).
// Every line that is not valid gets one error naming its line and column; a program with any
// error gives no blocks. Pure: no I/O, no machine, only the names of the machine's axes.
class ProgramParser
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramParser)
public:
    static constexpr int kMaxLineLength = 1024; // characters, as LinuxCNC's 256 but roomier
    static constexpr int kMaxLines = 1000000;
    static constexpr int kMaxErrors = 100;
    static constexpr qint64 kMaxRepeat = 1000000;
    static constexpr int kMaxNesting = 32;

    // axisNames: the machine's axes ("X", "A", ...); any other axis word is an error.
    explicit ProgramParser(const QStringList& axisNames);

    void feed(const QByteArray& bytes);
    // The program, or nullopt with *errors (every one, in line order, at most kMaxErrors).
    std::optional<Program> finish(QList<ProgramError>* errors);

    static std::optional<Program> parse(const QByteArray& text, const QStringList& axisNames,
                                        QList<ProgramError>* errors);

private:
    void endLine();
    void parseLine(const QString& text);
    // A line of only "%": the program's first or last line (LinuxCNC); true when handled.
    bool percentLine(const QString& text);
    void addBlock(ProgramBlock block);
    void noteBrokenRepeat(const LexedLine& lexed);
    void error(int line, int column, const QString& message);

    QStringList m_axisNames;
    QByteArray m_pending;
    bool m_pendingTooLong = false;
    int m_line = 0;
    ModalState m_modal;
    int m_endLine = 0;            // the line of M2/M30, once read
    bool m_anyWords = false;      // a line with words was read
    int m_percentOpen = 0;        // the line of the first "%", if any
    bool m_percentClosed = false; // the second "%": LinuxCNC ignores what follows it
    struct OpenRepeat
    {
        int index = -1; // of its block; -1: its line had an error (its endrepeat still fits)
        int oNumber = 0;
        int line = 0;
    };
    QList<OpenRepeat> m_openRepeats;
    Program m_program;
    QList<ProgramError> m_errors;
    bool m_tooManyErrors = false;
};

} // namespace stepdeck::program
