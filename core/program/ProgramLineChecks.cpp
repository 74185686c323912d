#include "ProgramLineChecks.h"
#include "ProgramLine.h"
#include <algorithm>

namespace stepdeck::program {

namespace {

// Which parameters an action takes (F is modal and may stand on any line).
QString allowedParameters(BlockKind kind)
{
    switch (kind) {
    case BlockKind::Dwell:
        return QStringLiteral("FP");
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
        return QStringLiteral("FP");
    case BlockKind::WaitInput:
        return QStringLiteral("FPLQ");
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
        return QStringLiteral("FIJKRP");
    case BlockKind::SetCoordinates:
        return QStringLiteral("FLPR");
    case BlockKind::DrillCycle:
        return QStringLiteral("FRQPL"); // which cycle takes Q or P: ProgramLine's drillCycle

    default:
        return QStringLiteral("F");
    }
}

bool takesAxes(BlockKind kind)
{
    return kind == BlockKind::Rapid || kind == BlockKind::Feed || kind == BlockKind::Home ||
           kind == BlockKind::Modal || isArc(kind) || kind == BlockKind::SetCoordinates ||
           kind == BlockKind::AxisOffset || kind == BlockKind::DrillCycle;
}

// LinuxCNC's arc planes (docs/programs.md "Arcs"): the two axes in the plane in the order
// their angle is measured (G18 measures from Z towards X, so that G2 is clockwise seen from
// +Y), the axis a helix moves, the centre's words and the G word that selects the plane.
struct PlaneWords
{
    QString axes;   // "XY", "ZX", "YZ"
    QChar helix;    // Z, Y, X
    QString centre; // "IJ", "KI", "JK"
    QString planeG; // "G17", "G18", "G19"
    QString name;   // "XY", "XZ", "YZ"
};

PlaneWords planeWords(Plane plane)
{
    switch (plane) {
    case Plane::XZ:
        return {QStringLiteral("ZX"), QLatin1Char('Y'), QStringLiteral("KI"), QStringLiteral("G18"),
                QStringLiteral("XZ")};
    case Plane::YZ:
        return {QStringLiteral("YZ"), QLatin1Char('X'), QStringLiteral("JK"), QStringLiteral("G19"),
                QStringLiteral("YZ")};
    case Plane::XY:
        break;
    }
    return {QStringLiteral("XY"), QLatin1Char('Z'), QStringLiteral("IJ"), QStringLiteral("G17"),
            QStringLiteral("XY")};
}

// "X5 is not used by G4": named by the line's main action, else the first beside it.
QString notTaken(const Words& words, const QString& word)
{
    const ProgramWord* action = words.actionWord         ? words.actionWord
                                : words.others.isEmpty() ? nullptr
                                                         : words.others.first().word;
    return action ? ProgramLine::tr("%1 is not used by %2").arg(word, action->valueText())
                  : ProgramLine::tr("%1 is not used on a line without an action").arg(word);
}

class Checker
{
public:
    Checker(const Words& words, const ProgramWord* action, ProgramBlock* block)
        : m_words(words), m_action(action), m_block(block)
    {}

    // The first missing or out-of-range word of the block's action: (column, message);
    // column 0: none.
    std::pair<int, QString> check()
    {
        switch (m_block->kind) {
        case BlockKind::Dwell:
            return number('P', 0, 1e6, false, &m_block->seconds);
        case BlockKind::OutputOn:
        case BlockKind::OutputOff:
            return whole('P', &m_block->number);
        case BlockKind::WaitInput:
            return waitInput();
        case BlockKind::ArcClockwise:
        case BlockKind::ArcCounterClockwise:
            return arc();
        case BlockKind::SetCoordinates:
            return setCoordinates();
        case BlockKind::AxisOffset:
            if (m_words.axes.isEmpty())
                return {m_action->column,
                        ProgramLine::tr("G92 needs axis words: the values the axes' present "
                                        "positions get")};
            return {};
        default:
            return {};
        }
    }

private:
    std::pair<int, QString> missing(QChar letter) const
    {
        return {m_action->column,
                ProgramLine::tr("%1 needs %2").arg(m_action->valueText(), QString(letter))};
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
            return {w->column, range.arg(w->valueText()).arg(qint64(min)).arg(qint64(max))};
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
            return {w->column, ProgramLine::tr("%1: the number must be a whole number 0..9999")
                                   .arg(w->valueText())};
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
                    ProgramLine::tr("%1: L3 waits for high, L4 for low").arg(l->valueText())};
        m_block->inputHigh = l->value == 3;
        return number('Q', 0, 1e6, true, &m_block->seconds);
    }

    // G2/G3 (LinuxCNC): axis words of the plane and its helix axis, the centre by the
    // plane's two of I J K or by R, P whole turns.
    std::pair<int, QString> arc()
    {
        const PlaneWords plane = planeWords(m_block->plane);
        const QString g = blockWord(m_block->kind);
        bool endInPlane = false;
        for (auto it = m_words.axes.cbegin(); it != m_words.axes.cend(); ++it) {
            const QChar l = it.key().at(0);
            endInPlane = endInPlane || plane.axes.contains(l);
            if (!plane.axes.contains(l) && l != plane.helix)
                return {it.value()->column,
                        ProgramLine::tr("%1: %2 in the %3 plane (%4) moves %5, %6 and %7 only")
                            .arg(it.value()->valueText(), g, plane.name, plane.planeG)
                            .arg(plane.axes.at(0))
                            .arg(plane.axes.at(1))
                            .arg(plane.helix)};
        }
        const ProgramWord* r = m_words.parameters.value('R');
        bool anyCentre = false;
        for (const QChar l : {QLatin1Char('I'), QLatin1Char('J'), QLatin1Char('K')}) {
            const ProgramWord* w = m_words.parameters.value(l);
            if (!w)
                continue;
            // The offset along the plane's normal: GRBL leaves it out, and FreeCAD's grbl post
            // writes K0 on every G17 arc; LinuxCNC refuses it. Left out when 0 (the parser
            // notes it), refused otherwise.
            if (!plane.centre.contains(l) && w->value == 0)
                continue;
            if (!plane.centre.contains(l))
                return {w->column, ProgramLine::tr("%1 is not used by %2 in the %3 plane (%4): "
                                                   "its centre takes %5 and %6")
                                       .arg(w->valueText(), g, plane.name, plane.planeG)
                                       .arg(plane.centre.at(0))
                                       .arg(plane.centre.at(1))};
            if (r)
                return {r->column, ProgramLine::tr("%1: an arc takes its centre by I, J, K or by "
                                                   "R, not both")
                                       .arg(r->valueText())};
            anyCentre = true;
            std::optional<double>& out = l == QLatin1Char('I')   ? m_block->arc.i
                                         : l == QLatin1Char('J') ? m_block->arc.j
                                                                 : m_block->arc.k;
            out = w->value;
        }
        if (!r && !anyCentre)
            return {m_action ? m_action->column : m_words.axes.first()->column,
                    ProgramLine::tr("%1 needs its centre: %2 and %3, or R")
                        .arg(g)
                        .arg(plane.centre.at(0))
                        .arg(plane.centre.at(1))};
        if (r) {
            if (r->value == 0)
                return {r->column,
                        ProgramLine::tr("%1: the radius must not be 0").arg(r->valueText())};
            if (!endInPlane)
                return {r->column, ProgramLine::tr("%1 with R needs an end point in the plane "
                                                   "(%2 or %3); a full circle takes %4 and %5")
                                       .arg(g)
                                       .arg(plane.axes.at(0))
                                       .arg(plane.axes.at(1))
                                       .arg(plane.centre.at(0))
                                       .arg(plane.centre.at(1))};
            m_block->arc.radius = r->value;
        }
        if (const ProgramWord* p = m_words.parameters.value('P')) {
            if (!isWhole(p->value) || p->value < 1 || p->value > kMaxArcTurns)
                return {p->column, ProgramLine::tr("%1: P counts the arc's turns, a whole number "
                                                   "1..%2")
                                       .arg(p->valueText())
                                       .arg(kMaxArcTurns)};
            m_block->arc.turns = int(p->value);
        }
        return {};
    }

    // G10 L2 P<n> (the offsets as written) and G10 L20 P<n> (the current point gets the words'
    // values) on G54 (P1) to G59 (P6), P0 the system in effect (LinuxCNC).
    std::pair<int, QString> setCoordinates()
    {
        if (const ProgramWord* r = m_words.parameters.value('R'))
            return {r->column, ProgramLine::tr("%1: G10 R (a rotated coordinate system) is not "
                                               "supported")
                                   .arg(r->valueText())};
        const ProgramWord* l = m_words.parameters.value('L');
        if (!l)
            return missing('L');
        if (l->value != 2 && l->value != 20)
            return {l->column, ProgramLine::tr("G10 %1 is not supported: L2 and L20 set the "
                                               "coordinate systems")
                                   .arg(l->valueText())};
        const ProgramWord* p = m_words.parameters.value('P');
        if (!p)
            return missing('P');
        if (!isWhole(p->value) || p->value < 0 || p->value > 6)
            return {p->column, ProgramLine::tr("%1: G10 sets P1 (G54) to P6 (G59), P0 the "
                                               "system in effect")
                                   .arg(p->valueText())};
        m_block->number = int(p->value);
        m_block->fromPosition = l->value == 20;
        return {};
    }

    const Words& m_words;
    const ProgramWord* m_action;
    ProgramBlock* m_block;
};

} // namespace

std::pair<int, QString> checkUnusedWords(const Words& words, BlockKind mainKind)
{
    const auto anyTakes = [&](const auto& takes) {
        return takes(mainKind) || std::any_of(words.others.cbegin(), words.others.cend(),
                                              [&](const LineAction& a) { return takes(a.kind); });
    };
    for (auto it = words.parameters.cbegin(); it != words.parameters.cend(); ++it) {
        if (it.key() == QLatin1Char('H') && words.lengthOffset == true)
            continue; // G43's (ProgramLine)
        if (it.key() == QLatin1Char('S'))
            continue; // modal, as F: any line may set the spindle's speed (LinuxCNC)
        const QChar letter = it.key();
        if (!anyTakes([letter](BlockKind k) { return allowedParameters(k).contains(letter); }))
            return {it.value()->column, notTaken(words, it.value()->valueText())};
    }
    if (!words.axes.isEmpty() && !anyTakes(takesAxes))
        return {words.axes.first()->column, notTaken(words, words.axes.first()->valueText())};
    return {};
}

std::pair<int, QString> checkActionWords(const Words& words, const ProgramWord* action,
                                         ProgramBlock* block)
{
    return Checker(words, action, block).check();
}

std::optional<ProgramBlock> repeatBlock(const LexedLine& line, const ProgramWord& o, int lineNumber,
                                        std::optional<ProgramError>* error)
{
    const auto fail = [&](int column, const QString& message) {
        *error = ProgramError{lineNumber, column, message};
        return std::nullopt;
    };
    if (!isWhole(o.value) || o.value < 0)
        return fail(o.column, ProgramLine::tr("%1: O takes a whole number").arg(o.valueText()));
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
