#include "ProgramLine.h"
#include "ProgramLineChecks.h"
#include <algorithm>
#include <cmath>

namespace stepdeck::program {

namespace {

// A polar coordinate's X or Y as the axis word it stands for, at the polar word's column; a
// value within rounding of 0 is 0 (cos 90 degrees is 6e-17, not 0).
ProgramWord polarWord(QChar letter, double value, double scale, int column)
{
    if (std::fabs(value) < 1e-12 * std::max(1.0, std::fabs(scale)))
        value = 0;
    ProgramWord w;
    w.letter = letter;
    w.value = value;
    w.column = column;
    w.written = (QString(letter) + figure(value)).toStdString();
    return w;
}

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
    block->comp = modal.comp;
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

// The line's blocks into *blocks: the actions beside the main one, and the main one unless they
// do all it would (modal words only, or S that a spindle switch on the line takes), in
// LinuxCNC's order. S goes out once, first (LinuxCNC's step 5), or with the line's M3/M4/M5;
// the message at the line's start; G43 applies after the tool change (step 18), with the
// line's last block.
std::optional<ProgramError> lineBlocks(const Words& sorted, const ProgramBlock& main,
                                       const LexedLine& line, const ModalState& modal,
                                       std::vector<ProgramBlock>* blocks)
{
    bool spindleSwitch = false;
    for (const LineAction& action : std::as_const(sorted.others)) {
        ProgramBlock o;
        if (const std::optional<ProgramError> e =
                actionBlock(sorted, action, main, line.comment, modal, &o))
            return e;
        spindleSwitch = spindleSwitch || isSpindleSwitch(o.kind);
        blocks->push_back(std::move(o));
    }
    const bool mainRuns =
        blocks->empty() ||
        (main.kind != BlockKind::Modal && !(main.kind == BlockKind::SpindleSpeed && spindleSwitch));
    if (mainRuns)
        blocks->push_back(main);
    std::stable_sort(blocks->begin(), blocks->end(),
                     [](const ProgramBlock& x, const ProgramBlock& y) {
                         return actionRole(x.kind).step < actionRole(y.kind).step;
                     });
    for (ProgramBlock& each : *blocks)
        each.spindleChange = false;
    if (main.spindleChange) {
        const auto taker = std::find_if(blocks->begin(), blocks->end(), [](const ProgramBlock& x) {
            return isSpindleSwitch(x.kind);
        });
        (taker != blocks->end() ? *taker : blocks->front()).spindleChange = true;
    }
    blocks->front().message = line.message;
    blocks->back().appliesLengthOffset = sorted.lengthOffset == true;
    return std::nullopt;
}

} // namespace

// LinuxCNC's polar coordinates (issue 50 item 6, docs/programs.md "Polar coordinates"): "@r ^a"
// is the point X = r cos a, Y = r sin a of the program's coordinates (its origin the work
// zero), a in degrees from +X, on any move. LinuxCNC also takes "@" or "^" alone (the other
// from where the tool stands) and G91's increments of both; those depend on the current point,
// which only the check and the run know, so they are refused with what to write instead.
std::pair<int, QString> applyPolar(Words* words, const ModalState& modal,
                                   const QStringList& axisNames)
{
    const ProgramWord* r = words->polarRadius;
    const ProgramWord* a = words->polarAngle;
    if (!r && !a)
        return {};
    const ProgramWord* first = r && a ? (r->column < a->column ? r : a) : (r ? r : a);
    const auto refuse = [first](const QString& why) { return std::pair{first->column, why}; };
    if (!axisNames.contains(QStringLiteral("X")) || !axisNames.contains(QStringLiteral("Y")))
        return refuse(ProgramLine::tr("polar coordinates (@, ^) need the axes X and Y (the "
                                      "machine has %1)")
                          .arg(axisNames.join(QStringLiteral(", "))));
    const std::optional<BlockKind> action = words->action;
    if (action && action != BlockKind::Rapid && action != BlockKind::Feed && !isArc(*action) &&
        action != BlockKind::DrillCycle)
        return refuse(ProgramLine::tr("%1 is not used by %2: polar coordinates give a move's end")
                          .arg(first->valueText(), words->actionWord->valueText()));
    if (modal.plane != Plane::XY)
        return refuse(ProgramLine::tr("polar coordinates (@, ^) work in the XY plane (G17) only, "
                                      "as in LinuxCNC"));
    for (const QString& axis : {QStringLiteral("X"), QStringLiteral("Y")})
        if (const ProgramWord* w = words->axes.value(axis))
            return {w->column, ProgramLine::tr("%1 beside polar coordinates (@, ^): give one or "
                                               "the other, as in LinuxCNC")
                                   .arg(w->valueText())};
    if (words->machineCoordinates)
        return refuse(ProgramLine::tr("polar coordinates (@, ^) are not machine coordinates: not "
                                      "with G53, as in LinuxCNC"));
    if (modal.relative)
        return refuse(ProgramLine::tr("polar coordinates in G91 add to where the tool stands: "
                                      "not supported; write @ and ^ in G90"));
    if (!r || !a)
        return refuse(ProgramLine::tr("%1 alone takes the other from where the tool stands: not "
                                      "supported; give both @ (the distance) and ^ (the angle)")
                          .arg(first->valueText()));
    const double angle = a->value * M_PI / 180.0;
    words->polarXY[0] =
        polarWord(QLatin1Char('X'), r->value * std::cos(angle), r->value, r->column);
    words->polarXY[1] =
        polarWord(QLatin1Char('Y'), r->value * std::sin(angle), r->value, a->column);
    words->axes.insert(QStringLiteral("X"), &words->polarXY[0]);
    words->axes.insert(QStringLiteral("Y"), &words->polarXY[1]);
    return {};
}

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
        if (modal->comp.on())
            return fail(first->column, tr("O%1 with cutter compensation on: G40 before it (a "
                                          "repeat's passes would enter the path anew)")
                                           .arg(first->valueText().mid(1)));
        if (last - first > 1)
            return fail(first[1].column,
                        tr("O%1 stands alone on its line").arg(first->valueText().mid(1)));
        std::optional<ProgramBlock> repeat = repeatBlock(line, *first, lineNumber, error);
        if (repeat)
            blocks->push_back(std::move(*repeat));
        return repeat.has_value();
    }
    Words sorted;
    if (!sortLineWords(lineNumber, axisNames, first, last, &sorted, error))
        return false;
    ModalState next = *modal;
    if (const auto [column, why] = applyModalWords(&sorted, &next); column > 0)
        return fail(column, why);
    if (const auto [column, why] = applyPolar(&sorted, next, axisNames); column > 0)
        return fail(column, why);
    ProgramBlock b;
    if (const auto [column, why] = fillBlock(sorted, &next, &b); column > 0)
        return fail(column, why);
    carryModal(next, &b);
    if (const std::optional<ProgramError> e = fillPrompt(line.comment, next, &b))
        return fail(e->column, e->message);
    if (const std::optional<ProgramError> e = lineBlocks(sorted, b, line, next, blocks))
        return fail(e->column, e->message);
    if (const auto [column, why] = checkCutterComp(sorted, *modal, &next, *blocks); column > 0)
        return fail(column, why);
    *modal = next;
    return true;
}

} // namespace stepdeck::program
