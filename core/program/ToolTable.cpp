// LinuxCNC's tool.tbl (LinuxCNC docs, "Tool Table Format"): T, P, the offsets per axis, D and
// a ";" comment; StepDeck uses T, Z (the length on the tool axis), D and the comment.
#include "ToolTable.h"
#include "ProgramLineChecks.h"
#include <QRegularExpression>
#include <cmath>

namespace stepdeck::program {

namespace {

struct Column
{
    QChar letter;
    double value = 0;
    int column = 0;
};

// "T1", "Z+0.5", "D3.": a letter and a finite number.
std::optional<Column> columnOf(const QString& token, int column)
{
    if (token.size() < 2 || !token.at(0).isLetter())
        return std::nullopt;
    bool ok = false;
    const double value = token.mid(1).toDouble(&ok);
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    return Column{token.at(0).toUpper(), value, column};
}

} // namespace

namespace {
// One line's columns into *tool: the first error (column, why), or column 0.
std::pair<int, QString> readTool(const QString& data, Tool* tool, bool* hasNumber)
{
    static const QRegularExpression token(QStringLiteral("\\S+"));
    for (auto it = token.globalMatch(data); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const int column = int(m.capturedStart()) + 1;
        const std::optional<Column> c = columnOf(m.captured(), column);
        const QString notAColumn =
            ToolTable::tr("%1 is not a column of a tool table (T, P, Z, D, ...)").arg(m.captured());
        if (!c)
            return {column, notAColumn};
        if (c->letter == QLatin1Char('T')) {
            if (!isWhole(c->value) || c->value < 0 || c->value > kMaxTool)
                return {column, ToolTable::tr("%1: T takes a tool number, whole, 0..%2")
                                    .arg(m.captured())
                                    .arg(kMaxTool)};
            tool->number = int(c->value);
            *hasNumber = true;
        } else if (c->letter == QLatin1Char('Z')) {
            tool->length = c->value;
        } else if (c->letter == QLatin1Char('D')) {
            if (c->value < 0)
                return {column, ToolTable::tr("%1: a diameter is not below 0").arg(m.captured())};
            tool->diameter = c->value;
        } else if (!QStringLiteral("PXYABCUVWIJQ").contains(c->letter)) {
            return {column, notAColumn};
        }
    }
    return {};
}
} // namespace

std::optional<ToolTable> ToolTable::parse(const QByteArray& text, QList<ProgramError>* errors)
{
    ToolTable table;
    QList<ProgramError> found;
    const QList<QByteArray> lines = text.split('\n');
    for (int n = 0; n < lines.size(); ++n) {
        QString line = QString::fromUtf8(lines.at(n));
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        const qsizetype semicolon = line.indexOf(QLatin1Char(';'));
        const QString data = semicolon < 0 ? line : line.left(semicolon);
        if (data.trimmed().isEmpty())
            continue;
        Tool tool;
        bool hasNumber = false;
        const auto [column, why] = readTool(data, &tool, &hasNumber);
        if (column > 0)
            found << ProgramError{n + 1, column, why};
        else if (!hasNumber)
            found << ProgramError{n + 1, 1, tr("the line names no tool (T)")};
        else if (table.m_tools.contains(tool.number))
            found << ProgramError{n + 1, 1, tr("tool %1 is in the table twice").arg(tool.number)};
        else if (table.m_tools.size() >= kMaxTools)
            found << ProgramError{n + 1, 1, tr("the table has more than %1 tools").arg(kMaxTools)};
        if (column > 0 || !hasNumber || table.m_tools.contains(tool.number) ||
            table.m_tools.size() >= kMaxTools)
            continue;
        tool.text = semicolon < 0 ? QString() : line.mid(semicolon + 1).trimmed();
        table.m_tools.insert(tool.number, tool);
    }
    if (errors)
        *errors = found;
    if (!found.isEmpty())
        return std::nullopt;
    return table;
}

QByteArray ToolTable::text() const
{
    QByteArray out;
    for (const Tool& t : m_tools) {
        QString line = QStringLiteral("T%1 P%1 Z%2 D%3")
                           .arg(t.number)
                           .arg(QString::number(t.length, 'g', 12))
                           .arg(QString::number(t.diameter, 'g', 12));
        if (!t.text.isEmpty())
            line += QStringLiteral(" ;") + t.text;
        out += line.toUtf8() + '\n';
    }
    return out;
}

const Tool* ToolTable::find(int number) const
{
    const auto it = m_tools.constFind(number);
    return it == m_tools.cend() ? nullptr : &it.value();
}

} // namespace stepdeck::program
