#pragma once
#include "program/ProgramBlock.h"
#include <QCoreApplication>
#include <QHash>
#include <QStringList>
#include <optional>

namespace stepdeck::program {

// An O-word line of LinuxCNC's language: "O<label> <keyword> [arguments]", an N number before
// it allowed. Labels are numbers ("o100", leading zeros left out) or names ("o<pocket>",
// lower case, spaces left out), as LinuxCNC reads them.
struct NgcStatement
{
    enum Kind : quint8 {
        Sub,
        EndSub,
        Call,
        Return,
        If,
        ElseIf,
        Else,
        EndIf,
        While,
        EndWhile,
        Do,
        Break,
        Continue,
        Repeat,
        EndRepeat,
        DoWhile, // the "while" that closes a do (NgcStructure tells it from a while)
    };
    Kind kind = Sub;
    QString label;
    int column = 0;     // of the O (1-based)
    qsizetype rest = 0; // where its arguments start (0-based)

    QString name() const; // "O100 while", for messages
    // "O100", "O<pocket>": a label as written in messages.
    static QString labelText(const QString& label);
    static const char* keyword(Kind kind);
    // The statement of a line; nullopt: none (*error set when the O word is broken).
    static std::optional<NgcStatement> read(QStringView line, int lineNumber,
                                            std::optional<ProgramError>* error);
};

// The O-word structure of one file, matched once before anything runs (LinuxCNC matches as it
// goes; a file with a broken structure is refused whole, so the check does not depend on the
// path). Lines are 0-based here.
class NgcStructure
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::NgcStructure)
public:
    // lineOffset: added to line numbers in messages (1 for the main file).
    static std::optional<NgcStructure> scan(const QStringList& lines, QList<ProgramError>* errors,
                                            int maxErrors);

    const NgcStatement* statement(int line) const
    {
        const auto it = m_statements.find(line);
        return it == m_statements.end() ? nullptr : &*it;
    }
    // sub -> endsub; if/elseif/else -> the next branch (or endif); while -> endwhile;
    // do -> its closing while; repeat -> endrepeat; and each end back to its start.
    int partner(int line) const { return m_partner.value(line, -1); }
    int endIf(int line) const { return m_endIf.value(line, -1); }
    int loopOf(int line) const { return m_loopOf.value(line, -1); } // break/continue -> start
    int subroutine(const QString& label) const { return m_subs.value(label, -1); }
    bool usesControl() const { return !m_statements.isEmpty(); }

private:
    class Scanner;
    QHash<int, NgcStatement> m_statements;
    QHash<int, int> m_partner;
    QHash<int, int> m_endIf;
    QHash<int, int> m_loopOf;
    QHash<QString, int> m_subs;
};

} // namespace stepdeck::program
