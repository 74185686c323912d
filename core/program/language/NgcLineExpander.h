#pragma once
#include "NgcParameters.h"
#include <QCoreApplication>
#include <QVarLengthArray>

namespace stepdeck::program {

// One ordinary line of LinuxCNC's language (not an O word) with its values worked out: the
// words with numbers in place of parameters and expressions, the "#…=" assignments (applied
// after the line by the caller, as LinuxCNC does), and (DEBUG, …)/(PRINT, …) made (MSG, …)
// with the parameters' values. Each word keeps its column where the text allows, so that the
// parser's errors on the line point where the operator wrote the word.
struct NgcExpandedLine
{
    QString text;
    struct Word
    {
        QChar letter;
        double value = 0;
        int column = 0; // in the source line (1-based)
    };
    QVarLengthArray<Word, 8> words;
    struct Assignment
    {
        NgcExpression::Reference target;
        double value = 0;
    };
    QList<Assignment> assignments;
    bool keep = false; // words, a comment or "%": the line goes to the parser

    bool has(char letter, double value) const;
};

class NgcLineExpander
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::NgcLineExpander)
public:
    // Words' values beyond this are refused (a coordinate, rate or number of StepDeck's fits).
    static constexpr double kMaxWordValue = 1e9;

    static std::optional<NgcExpandedLine> expand(QStringView line, int lineNumber,
                                                 const NgcParameters& parameters,
                                                 std::optional<ProgramError>* error);
    // A value as the parser reads it: up to six decimals, trailing zeros left out.
    static QString format(double value);
    // "#1", "#<name>" in a DEBUG/PRINT text replaced by their values (LinuxCNC).
    static QString substitute(QStringView text, const NgcParameters& parameters);

private:
    class Reader;
};

} // namespace stepdeck::program
