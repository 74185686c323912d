#pragma once
#include "program/ProgramBlock.h"
#include <QCoreApplication>
#include <QStringView>
#include <optional>

namespace stepdeck::program {

// Where an expression reads its parameters (NgcParameters): a value, or nullopt with *why.
class NgcParameterSource
{
public:
    virtual ~NgcParameterSource() = default;
    virtual std::optional<double> numbered(int number, QString* why) const = 0;
    // name: lower case, spaces left out ("_tool_len"); '_' first: global.
    virtual std::optional<double> named(const QString& name, QString* why) const = 0;
    virtual bool exists(const QString& name) const = 0;
};

// Reads and evaluates LinuxCNC's values in one line of text (rs274ngc's "real value"): a
// number, a parameter (#12, #<name>, #[expr]), an expression in [ ], a unary function
// (SIN[...], ATAN[y]/[x], EXISTS[#<name>]), each after an optional sign. Case does not matter
// and white space is left out anywhere, as LinuxCNC reads a line. Binary operators from the
// loosest: AND OR XOR, then EQ NE GT GE LT LE, + -, * / MOD, **; equal ones left to right
// (LinuxCNC's precedence). Angles in degrees. EQ and NE compare within 0.0001 (LinuxCNC's
// TOLERANCE_EQUAL); the others exactly. Pure: the parameters come from a source.
class NgcExpression
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::program::NgcExpression)
public:
    static constexpr double kEqualTolerance = 0.0001;
    static constexpr int kMaxDepth = 64; // brackets and functions nested (a bound on recursion)

    NgcExpression(QStringView line, const NgcParameterSource& parameters)
        : m_line(line), m_parameters(parameters)
    {}

    // A value from *pos (0-based); nullopt with error() set. *pos ends after the value.
    std::optional<double> readValue(qsizetype* pos);
    // "<name>" from *pos (after "#"): the name, lower case, spaces left out; empty: error().
    QString readName(qsizetype* pos);
    // The parameter number or name after '#' at *pos (the '#' is read): for an assignment.
    struct Reference
    {
        int number = 0; // 0: named
        QString name;
        int column = 0;
    };
    std::optional<Reference> readReference(qsizetype* pos);
    // An error at a 1-based column of the line.
    const std::optional<ProgramError>& error() const { return m_error; }
    void setLineNumber(int line) { m_lineNumber = line; }

private:
    std::optional<double> value(int depth);
    std::optional<double> bracketed(int depth); // "[expr]"
    std::optional<double> binary(int depth);    // up to the closing ']'
    std::optional<double> function(const QString& name, int column, int depth);
    std::optional<double> exists();
    std::optional<double> unary(const QString& name, double x, int column);
    static double logical(int op, double l, double r);
    std::optional<double> parameter(int depth);
    std::optional<double> number();
    bool apply(int op, double* left, double right, int column);
    int readOperator(); // -1: none at m_pos
    void skipSpaces();
    QChar peek() const;
    bool atEnd() const;
    int column() const { return int(m_pos) + 1; }
    std::nullopt_t fail(int column, const QString& message);
    bool failed(int column, const QString& message); // fail(), as false

    QStringView m_line;
    const NgcParameterSource& m_parameters;
    qsizetype m_pos = 0;
    int m_lineNumber = 0;
    std::optional<ProgramError> m_error;
};

} // namespace stepdeck::program
