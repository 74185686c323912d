#pragma once
#include "ProgramBlock.h"
#include <QCoreApplication>
#include <QVarLengthArray>
#include <string>

namespace stepdeck::program {

// One word of a line: its letter (upper case), its value and where the letter stands.
struct ProgramWord
{
    QChar letter;
    double value = 0;
    int column = 0; // 1-based
    // The letter and value as written, spaces left out ("G0.5", "P-1"; ASCII): for messages.
    // Kept as a std::string, whose short ones need no allocation (issue 29's rate).
    std::string written;

    QString valueText() const
    {
        return QString::fromLatin1(written.data(), qsizetype(written.size()));
    }
};

// A line split into words. O words carry their keyword ("repeat", "endrepeat") and the
// repeat count as written; comments give the first one's text (the M0 prompt).
// A line's words: in place up to 8 (a CAM line has a few; no allocation per line).
using ProgramWords = QVarLengthArray<ProgramWord, 8>;

struct LexedLine
{
    ProgramWords words;
    QString keyword; // after an O word, lower case
    int keywordColumn = 0;
    std::optional<double> keywordValue; // "O1 repeat [3]" -> 3
    int keywordValueColumn = 0;
    QString comment;
    QString message;                   // "(MSG, text)": the text for the operator (LinuxCNC)
    std::optional<ProgramError> error; // the first thing on the line that is not G-code
};

// Splits one line of the G-code subset (docs/programs.md) into words, the way LinuxCNC reads
// a line: letters in either case, white space anywhere between a letter and its value,
// "( ... )" comments anywhere (not nested), ";" to the end of the line. A value is a finite
// decimal: optional sign, digits, optional point and digits, no exponent. Pure; no state.
class ProgramLexer
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ProgramLexer)
public:
    static LexedLine lex(QStringView line, int lineNumber);
};

} // namespace stepdeck::program
