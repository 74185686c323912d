// ProgramLine's first step: a line's words sorted by role (Words), each checked against the
// others on the line: one of each modal group, the actions LinuxCNC runs together (issue 50),
// the axes the machine has, parameters at most once.
#include "ProgramLine.h"
#include "ProgramLineChecks.h"
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
const QString kParameterLetters = QStringLiteral("FSPLQIJKRHD");

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
        if (l == QLatin1Char('@') || l == QLatin1Char('^')) {
            const ProgramWord*& polar = l == QLatin1Char('@') ? out->polarRadius : out->polarAngle;
            if (polar)
                return ProgramLine::tr("%1 appears twice on the line").arg(l);
            polar = &w;
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
            return unsupportedWord(w, tenths);
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
            out->unitsWord = &w;
            return {};
        }
        const std::optional<BlockKind> action = g ? actionOfG(code) : actionOfM(code);
        if (!g && (code == 98 || code == 99)) // issue 33
            return ProgramLine::tr("%1 (a Fanuc-style subprogram) is not supported: write the "
                                   "subprogram as O<name> sub … endsub and call it with O<name> "
                                   "call")
                .arg(w.valueText());
        if (!action)
            return unsupportedWord(w, tenths);
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
        const int group = actionRole(action).group;
        const auto clashes = [&](BlockKind other) {
            const bool mistAndFlood =
                other != action &&
                (other == BlockKind::CoolantMist || other == BlockKind::CoolantFlood) &&
                (action == BlockKind::CoolantMist || action == BlockKind::CoolantFlood);
            return actionRole(other).group == group && !mistAndFlood;
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
        if (const QString why = refusalOf(tenths, w); !why.isEmpty())
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
        case 400:
        case 410:
        case 411:
        case 420:
        case 421:
            out->cutterComp = tenths;
            break;
        default: // G54..G59
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
        case 960:
        case 970:
            return 14; // G97 (rpm, LinuxCNC's default) is StepDeck's only spindle mode
        case 400:
        case 410:
        case 411:
        case 420:
        case 421:
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
    static QString refusalOf(int tenths, const ProgramWord& w)
    {
        switch (tenths) {
        case 950:
            return ProgramLine::tr("G95 (feed per revolution) is not supported: no controller "
                                   "reports its spindle's revolutions; use G94");
        case 960:
            return unsupportedWord(w, tenths);
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
} // namespace

ActionRole actionRole(BlockKind kind)
{
    switch (kind) {
    case BlockKind::SpindleSpeed: // S, no action word
        return {-1, 5};
    case BlockKind::OutputOn:
    case BlockKind::OutputOff:
    case BlockKind::WaitInput:
        return {105, 7};
    case BlockKind::ToolChange:
        return {106, 8};
    case BlockKind::SpindleOn:
    case BlockKind::SpindleReverse:
    case BlockKind::SpindleOff:
        return {107, 9};
    case BlockKind::CoolantMist:
    case BlockKind::CoolantFlood:
    case BlockKind::CoolantOff:
        return {108, 11};
    case BlockKind::Dwell:
        return {0, 14};
    case BlockKind::Home:
    case BlockKind::SetCoordinates:
    case BlockKind::AxisOffset:
    case BlockKind::AxisOffsetReset:
    case BlockKind::AxisOffsetSuspend:
    case BlockKind::AxisOffsetRestore:
        return {0, 23};
    case BlockKind::Rapid:
    case BlockKind::Feed:
    case BlockKind::ArcClockwise:
    case BlockKind::ArcCounterClockwise:
    case BlockKind::DrillCycle:
        return {1, 24};
    case BlockKind::Pause:
    case BlockKind::OptionalPause:
    case BlockKind::End:
        return {104, 25};
    default: // modal words only, repeats: no action word
        return {-1, 24};
    }
}

bool sortLineWords(int line, const QStringList& axisNames, const ProgramWord* first,
                   const ProgramWord* last, Words* out, std::optional<ProgramError>* error)
{
    return LineWords(line, axisNames).sort(first, last, out, error);
}

} // namespace stepdeck::program
