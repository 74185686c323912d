#include "ProgramLine.h"
#include "ProgramLineChecks.h"
#include <QSet>
#include <algorithm>
#include <cmath>

namespace stepdeck::program {

namespace {

const QString kAxisLetters = QStringLiteral("XYZABCUVW");

// "X", "A", ...: an axis letter as the QString the maps are keyed by, made once (a long program
// has millions of axis words; a QString per word would be an allocation each).
const QString& letterString(QChar l)
{
    static const QStringList letters = [] {
        QStringList out;
        for (char c = 'A'; c <= 'Z'; ++c)
            out << QString(QLatin1Char(c));
        return out;
    }();
    return letters.at(l.unicode() - 'A'); // callers pass one of kAxisLetters
}
const QString kParameterLetters = QStringLiteral("FSPLQIJKRH");

std::optional<BlockKind> actionOfG(int code)
{
    switch (code) {
    case 0:
        return BlockKind::Rapid;
    case 1:
        return BlockKind::Feed;
    case 2:
        return BlockKind::ArcClockwise;
    case 3:
        return BlockKind::ArcCounterClockwise;
    case 4:
        return BlockKind::Dwell;
    case 10:
        return BlockKind::SetCoordinates;
    case 28:
        return BlockKind::Home;
    case 73:
    case 81:
    case 82:
    case 83:
        return BlockKind::DrillCycle;
    case 92:
        return BlockKind::AxisOffset;
    default:
        return std::nullopt;
    }
}

std::optional<BlockKind> actionOfM(int code)
{
    switch (code) {
    case 0:
        return BlockKind::Pause;
    case 1:
        return BlockKind::OptionalPause;
    case 6:
        return BlockKind::ToolChange;
    case 2:
    case 30:
        return BlockKind::End;
    case 3:
        return BlockKind::SpindleOn;
    case 4:
        return BlockKind::SpindleReverse;
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
    bool sort(const ProgramWord* first, const ProgramWord* last, Words* out,
              std::optional<ProgramError>* error)
    {
        for (const ProgramWord* it = first; it != last; ++it) {
            const ProgramWord& w = *it;
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
            const QString& name = letterString(l);
            if (!m_axisNames.contains(name))
                return ProgramLine::tr("the machine has no axis %1 (it has %2)")
                    .arg(l)
                    .arg(m_axisNames.join(QStringLiteral(", ")));
            if (out->axes.contains(name))
                return ProgramLine::tr("axis %1 appears twice on the line").arg(l);
            out->axes.insert(name, &w);
            return {};
        }
        if (l == QLatin1Char('T')) {
            if (out->tool)
                return ProgramLine::tr("T appears twice on the line");
            if (!isWhole(w.value) || w.value < 0 || w.value > kMaxTool)
                return ProgramLine::tr("%1: T takes a tool number, whole, 0..%2")
                    .arg(w.valueText())
                    .arg(kMaxTool);
            out->tool = &w;
            return {};
        }
        if (l == QLatin1Char('N'))
            return ProgramLine::tr("N (a line number) stands only at the start of a line");
        if (l == QLatin1Char('O'))
            return ProgramLine::tr("O%1 stands alone on its line").arg(w.valueText().mid(1));
        return ProgramLine::tr("%1 is not a word of StepDeck programs").arg(w.valueText());
    }

    QString sortCode(const ProgramWord& w, Words* out)
    {
        const bool g = w.letter == QLatin1Char('G');
        // Codes in tenths: G61.1, G90.1 and G91.1 have a decimal digit (LinuxCNC).
        const double tenthsValue = w.value * 10;
        if (w.value < 0 || std::fabs(tenthsValue) > 1e9 || std::floor(tenthsValue) != tenthsValue)
            return ProgramLine::tr("%1 is not supported").arg(w.valueText());
        const int tenths = int(tenthsValue);
        if (g) {
            if (const std::optional<QString> modal = sortModalG(tenths, w, out))
                return *modal;
        }
        if (g && tenths == 530) { // G53: machine coordinates for this block (non-modal)
            if (out->machineCoordinates)
                return ProgramLine::tr("G53 appears twice on the line");
            out->machineCoordinates = &w;
            return {};
        }
        if (g && tenths > 920 && tenths < 924) // G92.1, G92.2, G92.3
            return setAction(tenths == 921   ? BlockKind::AxisOffsetReset
                             : tenths == 922 ? BlockKind::AxisOffsetSuspend
                                             : BlockKind::AxisOffsetRestore,
                             w, out);
        if (tenths % 10 != 0)
            return ProgramLine::tr("%1 is not supported").arg(w.valueText());
        const int code = tenths / 10;
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
        if (!g && (code == 98 || code == 99)) // issue 33
            return ProgramLine::tr("%1 (a Fanuc-style subprogram) is not supported: write the "
                                   "subprogram as O<name> sub … endsub and call it with O<name> "
                                   "call")
                .arg(w.valueText());
        if (!action)
            return ProgramLine::tr("%1 is not supported").arg(w.valueText());
        if (action == BlockKind::DrillCycle)
            out->cycleCode = code;
        return setAction(*action, w, out);
    }

    // LinuxCNC's whole line (issue 50, docs/programs.md "Several words on one line"): the
    // line's actions, at most one of each modal group (M7 and M8 together), at most four M
    // words, and of the actions that take words at most one that takes axis words and one
    // that takes P. The one with axis words is the main action, the others run beside it.
    QString setAction(BlockKind action, const ProgramWord& w, Words* out)
    {
        if (w.letter == QLatin1Char('M') && ++out->mWords > kMaxMWords)
            return ProgramLine::tr("%1: more than %2 M words on one line (LinuxCNC runs at most "
                                   "%2)")
                .arg(w.valueText())
                .arg(kMaxMWords);
        const int group = groupOf(action);
        const auto clashes = [&](BlockKind other) {
            const bool mistAndFlood =
                other != action &&
                (other == BlockKind::CoolantMist || other == BlockKind::CoolantFlood) &&
                (action == BlockKind::CoolantMist || action == BlockKind::CoolantFlood);
            return groupOf(other) == group && !mistAndFlood;
        };
        if (out->action && clashes(*out->action))
            return twoOfOneGroup(out->actionWord, w);
        for (const LineAction& other : std::as_const(out->others))
            if (clashes(other.kind))
                return twoOfOneGroup(other.word, w);
        if (isMotion(action) && out->groups.contains(kMotionGroup))
            return twoOfOneGroup(out->groups.value(kMotionGroup), w);
        if (!takesWords(action)) {
            out->others << LineAction{action, &w};
            return {};
        }
        if (!out->action) {
            out->action = action;
            out->actionWord = &w;
            return {};
        }
        const BlockKind main = *out->action;
        if (takesAxisWords(main) && takesAxisWords(action))
            return ProgramLine::tr("%1 and %2 both take axis words: write them on two lines")
                .arg(out->actionWord->valueText(), w.valueText());
        if (takesP(main) && takesP(action))
            return ProgramLine::tr("%1 and %2 both take P: write them on two lines")
                .arg(out->actionWord->valueText(), w.valueText());
        if (takesAxisWords(action)) { // "G4 P1 G1 X5": the move is the main action
            out->others << LineAction{main, out->actionWord};
            out->action = action;
            out->actionWord = &w;
        } else {
            out->others << LineAction{action, &w};
        }
        return {};
    }

    // The modal group of an action as LinuxCNC groups its words (G: 0 non-modal, 1 motion;
    // M: 4 stopping, 5 inputs and outputs, 6 tool change, 7 spindle, 8 coolant), M's offset by
    // 100 so that they meet no G group.
    static int groupOf(BlockKind kind)
    {
        switch (kind) {
        case BlockKind::Pause:
        case BlockKind::OptionalPause:
        case BlockKind::End:
            return 104;
        case BlockKind::OutputOn:
        case BlockKind::OutputOff:
        case BlockKind::WaitInput:
            return 105;
        case BlockKind::ToolChange:
            return 106;
        case BlockKind::SpindleOn:
        case BlockKind::SpindleReverse:
        case BlockKind::SpindleOff:
            return 107;
        case BlockKind::CoolantMist:
        case BlockKind::CoolantFlood:
        case BlockKind::CoolantOff:
            return 108;
        default:
            return isMotion(kind) ? kMotionGroup : 0;
        }
    }

    static bool takesAxisWords(BlockKind kind)
    {
        return isMotion(kind) || kind == BlockKind::Home || kind == BlockKind::SetCoordinates ||
               kind == BlockKind::AxisOffset;
    }

    static bool takesP(BlockKind kind)
    {
        return kind == BlockKind::Dwell || kind == BlockKind::OutputOn ||
               kind == BlockKind::OutputOff || kind == BlockKind::WaitInput ||
               kind == BlockKind::SetCoordinates || isArc(kind) || kind == BlockKind::DrillCycle;
    }

    // Whether an action has words of its own (axis words or parameters) on its line.
    static bool takesWords(BlockKind kind) { return takesAxisWords(kind) || takesP(kind); }

    static constexpr int kMaxMWords = 4;

    // The G words of LinuxCNC's modal groups that set a mode and move nothing (issue 29):
    // empty when sorted, a refusal with its reason, or nullopt for any other code.
    std::optional<QString> sortModalG(int tenths, const ProgramWord& w, Words* out)
    {
        const std::optional<int> group = modalGroupOf(tenths);
        if (!group)
            return std::nullopt;
        if (const QString why = refusalOf(tenths); !why.isEmpty())
            return why;
        if (const ProgramWord* other = out->groups.value(*group))
            return twoOfOneGroup(other, w);
        if (*group == kMotionGroup && isMotion(out->action))
            return twoOfOneGroup(out->actionWord, w); // G0 or G1 beside G80
        out->groups.insert(*group, &w);
        switch (tenths) {
        case 170:
        case 180:
        case 190:
            out->plane = tenths == 170 ? Plane::XY : tenths == 180 ? Plane::XZ : Plane::YZ;
            break;
        case 610:
            out->pathMode = PathMode::ExactPath;
            break;
        case 611:
            out->pathMode = PathMode::ExactStop;
            break;
        case 640:
            out->pathMode = PathMode::Blend;
            break;
        case 800:
            out->cancelsMotion = true;
            break;
        case 901:
        case 911:
            out->centreAbsolute = tenths == 901;
            break;
        case 430:
        case 490:
            out->lengthOffset = tenths == 430;
            break;
        case 980:
        case 990:
            out->retractToR = tenths == 990;
            break;
        case 930:
        case 940:
            out->inverseTime = tenths == 930;
            break;
        default: // G54..G59; G40: the mode StepDeck always runs in
            if (isCoordinateSystem(tenths))
                out->coordinateSystem = tenths / 10 - 54;
            break;
        }
        return QString();
    }

    // G54..G59 (tenths), LinuxCNC's modal group 12.
    static bool isCoordinateSystem(int tenths)
    {
        return tenths >= 540 && tenths <= 590 && tenths % 10 == 0;
    }

    // LinuxCNC's modal group of a mode-setting G code (tenths); nullopt for any other.
    static std::optional<int> modalGroupOf(int tenths)
    {
        if (isCoordinateSystem(tenths))
            return 12;
        switch (tenths) {
        case 800:
            return kMotionGroup; // G80 cancels the modal motion
        case 170:
        case 180:
        case 190:
            return 2;
        case 901:
        case 911:
            return 4;
        case 930:
        case 940:
        case 950:
            return 5;
        case 400:
        case 410:
        case 420:
            return 7;
        case 430:
        case 490:
            return 8;
        case 980:
        case 990:
            return 10;
        case 610:
        case 611:
        case 640:
            return 13;
        default:
            return std::nullopt;
        }
    }

    // Modes of those groups that StepDeck does not run, with what to do instead.
    static QString refusalOf(int tenths)
    {
        switch (tenths) {
        case 410:
        case 420:
            return ProgramLine::tr("G%1 (cutter radius compensation) is not supported: let the "
                                   "CAM post compensate the path (G40 is accepted)")
                .arg(tenths / 10);
        case 950:
            return ProgramLine::tr("G95 (feed per revolution) is not supported: no controller "
                                   "reports its spindle's revolutions; use G94");
        default:
            return {};
        }
    }

    // G0 to G3 and the drilling cycles: LinuxCNC's motion group, with G80 (G4 and G28 are of
    // no modal group).
    static bool isMotion(std::optional<BlockKind> action)
    {
        return action == BlockKind::Rapid || action == BlockKind::Feed ||
               action == BlockKind::DrillCycle || (action && isArc(*action));
    }

    static QString twoOfOneGroup(const ProgramWord* first, const ProgramWord& second)
    {
        return ProgramLine::tr("%1 and %2 on one line: they are of one modal group")
            .arg(first->valueText(), second.valueText());
    }

    static constexpr int kMotionGroup = 1;

    int m_line;
    const QStringList& m_axisNames;
};

// G53 (LinuxCNC): the words of this G0 or G1 are machine coordinates, absolute.
std::pair<int, QString> machineCoordinates(const Words& sorted, const ModalState& modal,
                                           ProgramBlock* b)
{
    const ProgramWord* g53 = sorted.machineCoordinates;
    if (!g53)
        return {};
    if (b->kind != BlockKind::Rapid && b->kind != BlockKind::Feed)
        return {g53->column, ProgramLine::tr("G53 moves in machine coordinates with G0 or G1 "
                                             "only")};
    if (modal.relative)
        return {g53->column, ProgramLine::tr("G53 takes absolute machine coordinates: not in G91")};
    b->machineCoordinates = true;
    return {};
}

// G93 (LinuxCNC's inverse time, docs/programs.md "Inverse time"): a G1, G2 or G3 takes 1/F
// minutes, so F stands on every such line that moves. Drilling cycles in G93 are refused, as
// LinuxCNC's interpreter refuses them (convert_cycle: "Cannot use inverse time feed with canned
// cycles"): a cycle's moves have no single time that F could give.
std::pair<int, QString> inverseTime(const Words& sorted, const ModalState& modal, ProgramBlock* b)
{
    if (!modal.inverseTime)
        return {};
    const int column = sorted.actionWord       ? sorted.actionWord->column
                       : sorted.axes.isEmpty() ? 1
                                               : sorted.axes.first()->column;
    if (b->kind == BlockKind::DrillCycle)
        return {column, ProgramLine::tr("a drilling cycle cannot run in inverse time (G93), as in "
                                        "LinuxCNC: switch to G94 and give F before the cycle")};
    if (!isArc(b->kind) && (b->kind != BlockKind::Feed || sorted.axes.isEmpty()))
        return {};
    if (!sorted.parameters.contains('F'))
        return {column, ProgramLine::tr("%1 in inverse time (G93) needs F on its line: the move "
                                        "takes 1/F minutes")
                            .arg(blockWord(b->kind))};
    b->inverseTime = true;
    return {};
}

// The block's kind, axes and word columns: its action, or the modal motion for a line of
// axis words; the modal motion afterwards into *modal.
std::pair<int, QString> fillBlock(const Words& sorted, ModalState* modal, ProgramBlock* b)
{
    b->kind = sorted.action.value_or(BlockKind::Modal);
    b->spindleChange = sorted.parameters.contains('S');
    if (!sorted.action && sorted.axes.isEmpty() && b->spindleChange)
        b->kind = BlockKind::SpindleSpeed; // "S12000" alone (LinuxCNC)
    if (!sorted.action && !sorted.axes.isEmpty()) {
        if (!modal->motion)
            return {sorted.axes.first()->column,
                    ProgramLine::tr("axis words need G0, G1, G2 or G3 before them")};
        b->kind = *modal->motion;
    }
    b->plane = modal->plane; // the arc's words depend on it
    b->arc.centreAbsolute = modal->centreAbsolute;
    b->coordinateSystem = modal->coordinateSystem; // G10 P0 names it
    if (const auto [column, why] = machineCoordinates(sorted, *modal, b); column > 0)
        return {column, why};
    if (const auto [column, why] = checkUnusedWords(sorted, b->kind); column > 0)
        return {column, why};
    if (const auto [column, why] = checkActionWords(sorted, sorted.actionWord, b); column > 0)
        return {column, why};
    const bool arc = isArc(b->kind);
    const bool cycle = b->kind == BlockKind::DrillCycle;
    if (const auto [column, why] = inverseTime(sorted, *modal, b); column > 0)
        return {column, why};
    if ((b->kind == BlockKind::Feed || arc || cycle) && (!sorted.axes.isEmpty() || arc || cycle) &&
        !modal->feed)
        return {sorted.actionWord ? sorted.actionWord->column : sorted.axes.first()->column,
                ProgramLine::tr("%1 needs a feed rate: F on this line or an earlier one")
                    .arg(cycle ? QStringLiteral("G%1").arg(sorted.cycleCode > 0 ? sorted.cycleCode
                                                                                : modal->cycleCode)
                               : blockWord(b->kind))};
    if (cycle) {
        if (const auto [column, why] = drillCycle(sorted, modal, b); column > 0)
            return {column, why};
    } else if (arc) {
        modal->motion = b->kind; // an arc always moves (its centre words are on the line)
    } else if (b->kind == BlockKind::Rapid || b->kind == BlockKind::Feed) {
        modal->motion = b->kind;
        // A motion word without axis words ("G1", "G1 F100") only sets the modal motion and
        // feed, as in LinuxCNC: nothing moves, so nothing can refuse it (issue 28); with S
        // ("G1 S0", LightBurn) it sets the spindle's speed.
        if (sorted.axes.isEmpty())
            b->kind = b->spindleChange ? BlockKind::SpindleSpeed : BlockKind::Modal;
    }
    for (auto it = sorted.axes.cbegin(); it != sorted.axes.cend(); ++it) {
        b->axes.insert(it.key(), it.value()->value);
        b->columns.insert(it.key(), it.value()->column);
    }
    if (cycle)
        b->axes.remove(QStringLiteral("Z")); // the hole's bottom: b->cycle.bottom
    for (auto it = sorted.parameters.cbegin(); it != sorted.parameters.cend(); ++it)
        b->columns.insert(QString(it.key()), it.value()->column);
    b->actionColumn = sorted.actionWord ? sorted.actionWord->column : 0;
    return {};
}

// The modal state in effect for a block.
void carryModal(const ModalState& modal, ProgramBlock* block)
{
    block->relative = modal.relative;
    block->inches = modal.inches;
    block->feed = modal.feed;
    block->rpm = modal.spindleSpeed;
    block->plane = modal.plane;
    block->coordinateSystem = modal.coordinateSystem;
    block->lengthTool = modal.lengthTool;
    block->pathMode = modal.pathMode;
    block->pathTolerance = modal.pathTolerance;
}

// LinuxCNC's order of execution (docs/programs.md "Several words on one line"): where an
// action of a line runs among the others (its step in LinuxCNC's table).
int executionStep(BlockKind kind)
{
    switch (kind) {
    case BlockKind::SpindleSpeed:
        return 5;
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
    case BlockKind::WaitInput:
        return 7;
    case BlockKind::ToolChange:
        return 8;
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
    case BlockKind::SpindleOff:
        return 9;
    case BlockKind::CoolantMist:
    case BlockKind::CoolantFlood:
    case BlockKind::CoolantOff:
        return 11;
    case BlockKind::Dwell:
        return 14;
    case BlockKind::Home:
    case BlockKind::SetCoordinates:
    case BlockKind::AxisOffset:
    case BlockKind::AxisOffsetReset:
    case BlockKind::AxisOffsetSuspend:
    case BlockKind::AxisOffsetRestore:
        return 23;
    case BlockKind::Pause:
    case BlockKind::OptionalPause:
    case BlockKind::End:
        return 25;
    default: // the motion, or modal words only
        return 24;
    }
}

bool isSpindleSwitch(BlockKind kind)
{
    return kind == BlockKind::SpindleOn || kind == BlockKind::SpindleReverse ||
           kind == BlockKind::SpindleOff;
}

// M0, M1: the line's comment; M6: the tool (T on this line or an earlier one) and its prompt.
std::optional<ProgramError> fillPrompt(const QString& comment, const ModalState& modal,
                                       ProgramBlock* b)
{
    if (b->kind == BlockKind::Pause || b->kind == BlockKind::OptionalPause)
        b->prompt = comment;
    if (b->kind != BlockKind::ToolChange)
        return std::nullopt;
    // LinuxCNC: T selects the tool, M6 changes to it. StepDeck's machines change tools by hand:
    // the program holds until the operator loaded it and resumes.
    if (!modal.tool)
        return ProgramError{0, b->actionColumn,
                            ProgramLine::tr("M6 needs a tool: T on this line or an earlier one")};
    b->number = *modal.tool;
    b->prompt = comment.isEmpty()
                    ? ProgramLine::tr("Load tool %1").arg(*modal.tool)
                    : ProgramLine::tr("Load tool %1 (%2)").arg(*modal.tool).arg(comment);
    return std::nullopt;
}

// An action beside the line's main one as a block of its own: the line's modal state and
// columns, the action's values.
std::optional<ProgramError> actionBlock(const Words& sorted, const LineAction& action,
                                        const ProgramBlock& main, const QString& comment,
                                        const ModalState& modal, ProgramBlock* out)
{
    out->kind = action.kind;
    out->actionColumn = action.word->column;
    out->columns = main.columns;
    carryModal(modal, out);
    if (const auto [column, why] = checkActionWords(sorted, action.word, out); column > 0)
        return ProgramError{0, column, why};
    return fillPrompt(comment, modal, out);
}

} // namespace

bool ProgramLine::parse(const LexedLine& line, int lineNumber, const QStringList& axisNames,
                        ModalState* modal, std::vector<ProgramBlock>* blocks,
                        std::optional<ProgramError>* error)
{
    blocks->clear();
    const auto fail = [&](int column, const QString& message) {
        *error = ProgramError{lineNumber, column, message};
        blocks->clear();
        return false;
    };
    // The words after an N number (Words point into line.words).
    const ProgramWord* first = line.words.cbegin();
    const ProgramWord* const last = line.words.cend();
    if (first == last && line.message.isEmpty())
        return true;
    if (first == last) { // only "(MSG, text)": a block that says it and does nothing else
        ProgramBlock b;
        b.message = line.message;
        carryModal(*modal, &b);
        blocks->push_back(std::move(b));
        return true;
    }
    if (first->letter == QLatin1Char('N')) {
        if (!isWhole(first->value) || first->value < 0)
            return fail(first->column, tr("%1: N takes a whole number").arg(first->valueText()));
        ++first;
    }
    if (first != last && first->letter == QLatin1Char('O')) {
        if (last - first > 1)
            return fail(first[1].column,
                        tr("O%1 stands alone on its line").arg(first->valueText().mid(1)));
        std::optional<ProgramBlock> repeat = repeatBlock(line, *first, lineNumber, error);
        if (repeat)
            blocks->push_back(std::move(*repeat));
        return repeat.has_value();
    }
    Words sorted;
    if (!LineWords(lineNumber, axisNames).sort(first, last, &sorted, error))
        return false;
    ModalState next = *modal;
    if (const auto [column, why] = applyModalWords(&sorted, &next); column > 0)
        return fail(column, why);
    ProgramBlock b;
    if (const auto [column, why] = fillBlock(sorted, &next, &b); column > 0)
        return fail(column, why);
    carryModal(next, &b);
    if (const std::optional<ProgramError> e = fillPrompt(line.comment, next, &b))
        return fail(e->column, e->message);
    // The actions beside the main one, each a block of the line, in LinuxCNC's order.
    const bool speed = b.spindleChange;
    bool spindleSwitch = false;
    for (const LineAction& action : std::as_const(sorted.others)) {
        ProgramBlock o;
        if (const std::optional<ProgramError> e =
                actionBlock(sorted, action, b, line.comment, next, &o))
            return fail(e->column, e->message);
        spindleSwitch = spindleSwitch || isSpindleSwitch(o.kind);
        blocks->push_back(std::move(o));
    }
    // The main block runs unless the others do all it would: modal words only, or S that a
    // spindle switch on the line takes.
    const bool mainRuns =
        blocks->empty() ||
        (b.kind != BlockKind::Modal && !(b.kind == BlockKind::SpindleSpeed && spindleSwitch));
    if (mainRuns)
        blocks->push_back(b);
    std::stable_sort(blocks->begin(), blocks->end(),
                     [](const ProgramBlock& x, const ProgramBlock& y) {
                         return executionStep(x.kind) < executionStep(y.kind);
                     });
    // S goes out once, first (LinuxCNC's step 5), or with the line's M3/M4/M5; the message at
    // the line's start; G43 applies after the tool change (step 18), with the line's last block.
    for (ProgramBlock& each : *blocks)
        each.spindleChange = false;
    if (speed) {
        const auto taker = std::find_if(blocks->begin(), blocks->end(), [](const ProgramBlock& x) {
            return isSpindleSwitch(x.kind);
        });
        (taker != blocks->end() ? *taker : blocks->front()).spindleChange = true;
    }
    blocks->front().message = line.message;
    blocks->back().appliesLengthOffset = sorted.lengthOffset == true;
    *modal = next;
    return true;
}

} // namespace stepdeck::program
