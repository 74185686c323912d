#include "ProgramLine.h"
#include <QSet>
#include <cmath>

namespace stepdeck::program {

namespace {

const QString kAxisLetters = QStringLiteral("XYZABCUVW");
const QString kParameterLetters = QStringLiteral("FSPLQ");

bool isWhole(double v)
{
    return std::floor(v) == v && std::fabs(v) < 1e9;
}

// A line's words sorted by role: at most one action, the modal words, the parameters and the
// axes, each at most once.
struct Words
{
    std::optional<BlockKind> action;
    const ProgramWord* actionWord = nullptr;
    std::optional<bool> relative; // G90 / G91
    std::optional<bool> inches;   // G21 / G20
    QMap<QChar, const ProgramWord*> parameters;
    QMap<QString, const ProgramWord*> axes;
};

std::optional<BlockKind> actionOfG(int code)
{
    switch (code) {
    case 0:
        return BlockKind::Rapid;
    case 1:
        return BlockKind::Feed;
    case 4:
        return BlockKind::Dwell;
    case 28:
        return BlockKind::Home;
    default:
        return std::nullopt;
    }
}

std::optional<BlockKind> actionOfM(int code)
{
    switch (code) {
    case 0:
        return BlockKind::Pause;
    case 2:
    case 30:
        return BlockKind::End;
    case 3:
        return BlockKind::SpindleOn;
    case 5:
        return BlockKind::SpindleOff;
    case 7:
        return BlockKind::CoolantMist;
    case 8:
        return BlockKind::CoolantFlood;
    case 9:
        return BlockKind::CoolantOff;
    case 64:
        return BlockKind::OutputOn;
    case 65:
        return BlockKind::OutputOff;
    case 66:
        return BlockKind::WaitInput;
    default:
        return std::nullopt;
    }
}

class LineWords
{
public:
    LineWords(int line, const QStringList& axisNames) : m_line(line), m_axisNames(axisNames) {}

    // Sorts every word; false with *error at the first that does not fit.
    bool sort(const QList<ProgramWord>& words, Words* out, std::optional<ProgramError>* error)
    {
        for (const ProgramWord& w : words) {
            const QString why = sortWord(w, out);
            if (!why.isEmpty()) {
                *error = ProgramError{m_line, w.column, why};
                return false;
            }
        }
        return true;
    }

private:
    QString sortWord(const ProgramWord& w, Words* out)
    {
        const QChar l = w.letter;
        if (l == QLatin1Char('G') || l == QLatin1Char('M'))
            return sortCode(w, out);
        if (kParameterLetters.contains(l)) {
            if (out->parameters.contains(l))
                return ProgramLine::tr("%1 appears twice on the line").arg(l);
            out->parameters.insert(l, &w);
            return {};
        }
        if (kAxisLetters.contains(l)) {
            if (!m_axisNames.contains(QString(l)))
                return ProgramLine::tr("the machine has no axis %1 (it has %2)")
                    .arg(l)
                    .arg(m_axisNames.join(QStringLiteral(", ")));
            if (out->axes.contains(QString(l)))
                return ProgramLine::tr("axis %1 appears twice on the line").arg(l);
            out->axes.insert(QString(l), &w);
            return {};
        }
        if (l == QLatin1Char('N'))
            return ProgramLine::tr("N (a line number) stands only at the start of a line");
        if (l == QLatin1Char('O'))
            return ProgramLine::tr("O%1 stands alone on its line").arg(w.valueText.mid(1));
        return ProgramLine::tr("%1 is not a word of StepDeck programs").arg(w.valueText);
    }

    QString sortCode(const ProgramWord& w, Words* out)
    {
        const bool g = w.letter == QLatin1Char('G');
        if (!isWhole(w.value) || w.value < 0)
            return ProgramLine::tr("%1 is not supported").arg(w.valueText);
        const int code = int(w.value);
        if (g && (code == 90 || code == 91)) {
            if (out->relative)
                return ProgramLine::tr("G90 and G91 on one line");
            out->relative = code == 91;
            return {};
        }
        if (g && (code == 20 || code == 21)) {
            if (out->inches)
                return ProgramLine::tr("G20 and G21 on one line");
            out->inches = code == 20;
            return {};
        }
        const std::optional<BlockKind> action = g ? actionOfG(code) : actionOfM(code);
        if (!action)
            return ProgramLine::tr("%1 is not supported").arg(w.valueText);
        if (out->action)
            return ProgramLine::tr("one action per line: %1 and %2")
                .arg(out->actionWord->valueText, w.valueText);
        out->action = action;
        out->actionWord = &w;
        return {};
    }

    int m_line;
    const QStringList& m_axisNames;
};

} // namespace

namespace {

// Which parameters an action takes (F is modal and may stand on any line).
QString allowedParameters(BlockKind kind)
{
    switch (kind) {
    case BlockKind::Dwell:
        return QStringLiteral("FP");
    case BlockKind::SpindleOn:
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

} // namespace

std::optional<ProgramBlock> ProgramLine::parse(const LexedLine& line, int lineNumber,
                                               const QStringList& axisNames, ModalState* modal,
                                               std::optional<ProgramError>* error)
{
    const auto fail = [&](int column, const QString& message) {
        *error = ProgramError{lineNumber, column, message};
        return std::nullopt;
    };
    QList<ProgramWord> words = line.words;
    if (words.isEmpty())
        return std::nullopt;
    if (words.first().letter == QLatin1Char('N')) {
        if (!isWhole(words.first().value) || words.first().value < 0)
            return fail(words.first().column,
                        tr("%1: N takes a whole number").arg(words.first().valueText));
        words.removeFirst();
    }
    if (!words.isEmpty() && words.first().letter == QLatin1Char('O')) {
        if (words.size() > 1)
            return fail(words.at(1).column,
                        tr("O%1 stands alone on its line").arg(words.first().valueText.mid(1)));
        return repeatBlock(line, words.first(), lineNumber, error);
    }
    Words sorted;
    if (!LineWords(lineNumber, axisNames).sort(words, &sorted, error))
        return std::nullopt;
    ModalState next = *modal;
    if (sorted.relative)
        next.relative = *sorted.relative;
    if (sorted.inches)
        next.inches = *sorted.inches;
    if (const ProgramWord* f = sorted.parameters.value('F')) {
        if (f->value <= 0)
            return fail(f->column,
                        tr("%1: the feed rate must be greater than 0").arg(f->valueText));
        next.feed = f->value;
    }
    ProgramBlock b;
    b.kind = sorted.action.value_or(BlockKind::Modal);
    if (!sorted.action && !sorted.axes.isEmpty()) {
        if (!next.motion)
            return fail(sorted.axes.first()->column, tr("axis words need G0 or G1 before them"));
        b.kind = *next.motion;
    }
    if (const auto [column, why] = Checker(sorted, &b).check(); column > 0)
        return fail(column, why);
    if (b.kind == BlockKind::Feed && !sorted.axes.isEmpty() && !next.feed)
        return fail(sorted.actionWord ? sorted.actionWord->column : sorted.axes.first()->column,
                    tr("G1 needs a feed rate: F on this line or an earlier one"));
    if (b.kind == BlockKind::Rapid || b.kind == BlockKind::Feed)
        next.motion = b.kind;
    for (auto it = sorted.axes.cbegin(); it != sorted.axes.cend(); ++it)
        b.axes.insert(it.key(), it.value()->value);
    b.relative = next.relative;
    b.inches = next.inches;
    b.feed = next.feed;
    if (b.kind == BlockKind::Pause)
        b.prompt = line.comment;
    *modal = next;
    return b;
}

} // namespace stepdeck::program
