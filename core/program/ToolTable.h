#pragma once
#include "ProgramBlock.h"
#include <QCoreApplication>
#include <QMap>
#include <optional>

namespace stepdeck::program {

// One tool of a machine's table (issue 29): its number, its length (the tool length offset
// G43 applies on the tool axis, in that axis' unit), its diameter and a text for the operator.
struct Tool
{
    int number = 0;
    double length = 0;
    double diameter = 0;
    QString text;

    bool operator==(const Tool& o) const
    {
        return number == o.number && length == o.length && diameter == o.diameter && text == o.text;
    }
};

// A machine's tool table in LinuxCNC's tool.tbl format (docs/programs.md "Tools"): one tool a
// line, "T<n> [P<pocket>] [Z<length>] [D<diameter>] [;text]", other LinuxCNC columns (X Y A B C
// U V W I J Q) read and ignored, blank lines and lines starting with ";" skipped. Pure.
class ToolTable
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::ToolTable)
public:
    static constexpr int kMaxTools = 10000;

    // nullopt with *errors (line:column: why), every one, when the text is not a table.
    static std::optional<ToolTable> parse(const QByteArray& text, QList<ProgramError>* errors);
    QByteArray text() const; // the table as tool.tbl lines, by tool number

    bool isEmpty() const { return m_tools.isEmpty(); }
    const Tool* find(int number) const;
    const QMap<int, Tool>& tools() const { return m_tools; }
    void insert(const Tool& tool) { m_tools.insert(tool.number, tool); }
    bool operator==(const ToolTable& o) const { return m_tools == o.m_tools; }

private:
    QMap<int, Tool> m_tools;
};

} // namespace stepdeck::program
