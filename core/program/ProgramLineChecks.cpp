#include "ProgramLineChecks.h"
#include "ProgramLine.h"

namespace stepdeck::program {

namespace {

// Which parameters an action takes (F is modal and may stand on any line).
QString allowedParameters(BlockKind kind)
{
    switch (kind) {
    case BlockKind::Dwell:
        return QStringLiteral("FP");
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
        return QStringLiteral("FS");
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
        return QStringLiteral("FP");
    case BlockKind::WaitInput:
        return QStringLiteral("FPLQ");
    default:
        return QStringLiteral("F");
    }
}

bool takesAxes(BlockKind kind)
{
    return kind == BlockKind::Rapid || kind == BlockKind::Feed || kind == BlockKind::Home ||
           kind == BlockKind::Modal;
}

class Checker
{
public:
    Checker(const Words& words, ProgramBlock* block) : m_words(words), m_block(block) {}

    // The first misplaced or missing word: (column, message); column 0: none.
    std::pair<int, QString> check()
    {
        const BlockKind kind = m_block->kind;
        for (auto it = m_words.parameters.cbegin(); it != m_words.parameters.cend(); ++it) {
            if (!allowedParameters(kind).contains(it.key()))
                return {it.value()->column, notTaken(it.value()->valueText)};
        }
        if (!takesAxes(kind) && !m_words.axes.isEmpty())
            return {m_words.axes.first()->column, notTaken(m_words.axes.first()->valueText)};
        switch (kind) {
        case BlockKind::Dwell:
            return number('P', 0, 1e6, false, &m_block->seconds);
        case BlockKind::SpindleOn:
        case BlockKind::SpindleReverse:
            return number('S', 0, 1e6, false, &m_block->rpm);
        case BlockKind::OutputOn:
        case BlockKind::OutputOff:
            return whole('P', &m_block->number);
        case BlockKind::WaitInput:
            return waitInput();
        default:
            return {};
        }
    }

private:
    QString notTaken(const QString& word) const
    {
        return m_words.actionWord
                   ? ProgramLine::tr("%1 is not used by %2")
                         .arg(word, m_words.actionWord->valueText)
                   : ProgramLine::tr("%1 is not used on a line without an action").arg(word);
    }

    std::pair<int, QString> missing(QChar letter) const
    {
        return {m_words.actionWord->column,
                ProgramLine::tr("%1 needs %2").arg(m_words.actionWord->valueText, QString(letter))};
    }

    std::pair<int, QString> number(QChar letter, double min, double max, bool open, double* out)
    {
        const ProgramWord* w = m_words.parameters.value(letter);
        if (!w)
            return missing(letter);
        if (w->value < min || w->value > max || (open && w->value == min)) {
            const QString range = open
                                      ? ProgramLine::tr("%1 must be greater than %2 and at most %3")
                                      : ProgramLine::tr("%1 must lie within %2..%3");
            return {w->column, range.arg(w->valueText).arg(qint64(min)).arg(qint64(max))};
        }
        *out = w->value;
        return {};
    }

    std::pair<int, QString> whole(QChar letter, int* out)
    {
        const ProgramWord* w = m_words.parameters.value(letter);
        if (!w)
            return missing(letter);
        if (!isWhole(w->value) || w->value < 0 || w->value > 9999)
            return {
                w->column,
                ProgramLine::tr("%1: the number must be a whole number 0..9999").arg(w->valueText)};
        *out = int(w->value);
        return {};
    }

    std::pair<int, QString> waitInput()
    {
        if (auto e = whole('P', &m_block->number); e.first)
            return e;
        const ProgramWord* l = m_words.parameters.value('L');
        if (!l)
            return missing('L');
        if (l->value != 3 && l->value != 4)
            return {l->column,
                    ProgramLine::tr("%1: L3 waits for high, L4 for low").arg(l->valueText)};
        m_block->inputHigh = l->value == 3;
        return number('Q', 0, 1e6, true, &m_block->seconds);
    }

    const Words& m_words;
    ProgramBlock* m_block;
};

} // namespace

std::pair<int, QString> checkActionWords(const Words& words, ProgramBlock* block)
{
    return Checker(words, block).check();
}

std::optional<ProgramBlock> repeatBlock(const LexedLine& line, const ProgramWord& o, int lineNumber,
                                        std::optional<ProgramError>* error)
{
    const auto fail = [&](int column, const QString& message) {
        *error = ProgramError{lineNumber, column, message};
        return std::nullopt;
    };
    if (!isWhole(o.value) || o.value < 0)
        return fail(o.column, ProgramLine::tr("%1: O takes a whole number").arg(o.valueText));
    ProgramBlock b;
    b.oNumber = int(o.value);
    b.actionColumn = o.column;
    if (line.keyword == QLatin1String("endrepeat")) {
        b.kind = BlockKind::RepeatEnd;
        return b;
    }
    if (line.keyword != QLatin1String("repeat"))
        return fail(
            line.keywordColumn ? line.keywordColumn : o.column,
            ProgramLine::tr("only \"O%1 repeat [count]\" and \"O%1 endrepeat\" are supported")
                .arg(b.oNumber));
    const std::optional<double> count = line.keywordValue;
    if (!count)
        return fail(line.keywordColumn,
                    ProgramLine::tr("repeat needs a count: O%1 repeat [3]").arg(b.oNumber));
    if (!isWhole(*count) || *count < 0 || *count > 1000000)
        return fail(line.keywordValueColumn,
                    ProgramLine::tr("the repeat count must be a whole number 0..1000000"));
    b.kind = BlockKind::RepeatStart;
    b.count = qint64(*count);
    return b;
}

} // namespace stepdeck::program
