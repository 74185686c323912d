// ProgramLine's modal words (LinuxCNC's modal groups: path control, tool length offset,
// units, distance, feed, spindle speed) and the drilling cycles' numbers, each into the modal
// state a program carries from line to line.
#include "CutterCompensation.h"
#include "ProgramLine.h"
#include "ProgramLineChecks.h"
#include <algorithm>

namespace stepdeck::program {

namespace {

// G61, G61.1, G64 into *modal; G64's P (the path tolerance, >= 0) and Q (the naive CAM
// tolerance, accepted as LinuxCNC does) are its own and leave the line's parameters.
std::pair<int, QString> applyPathMode(Words* words, ModalState* modal)
{
    if (!words->pathMode)
        return {};
    modal->pathMode = *words->pathMode;
    modal->pathTolerance.reset();
    if (*words->pathMode != PathMode::Blend)
        return {};
    if (const ProgramWord* p = words->parameters.value('P')) {
        if (p->value < 0)
            return {p->column,
                    ProgramLine::tr("%1: G64 P is a tolerance, not below 0").arg(p->valueText())};
        modal->pathTolerance = p->value;
        words->parameters.remove('P');
    }
    if (const ProgramWord* q = words->parameters.value('Q')) {
        if (q->value < 0)
            return {q->column,
                    ProgramLine::tr("%1: G64 Q is a tolerance, not below 0").arg(q->valueText())};
        words->parameters.remove('Q');
    }
    return {};
}

// G43 [H<n>] / G49 (LinuxCNC): the tool whose length offsets Z from this line on. Without H,
// the tool loaded by M6 (one on this line counts: LinuxCNC changes the tool before it applies
// the offset).
std::pair<int, QString> applyLengthOffset(const Words* words, ModalState* modal)
{
    const bool toolChange =
        words->action == BlockKind::ToolChange ||
        std::any_of(words->others.cbegin(), words->others.cend(),
                    [](const LineAction& a) { return a.kind == BlockKind::ToolChange; });
    if (toolChange && modal->tool)
        modal->loadedTool = modal->tool;
    const ProgramWord* h = words->parameters.value('H');
    if (!words->lengthOffset || !*words->lengthOffset) {
        if (words->lengthOffset)
            modal->lengthTool = -1; // G49
        if (h)
            return {h->column, ProgramLine::tr("%1 is used only with G43").arg(h->valueText())};
        return {};
    }
    if (h) {
        if (!isWhole(h->value) || h->value < 0 || h->value > kMaxTool)
            return {h->column, ProgramLine::tr("%1: H takes a tool number, whole, 0..%2")
                                   .arg(h->valueText())
                                   .arg(kMaxTool)};
        modal->lengthTool = int(h->value);
        return {};
    }
    if (!modal->loadedTool)
        return {words->groups.value(8)->column,
                ProgramLine::tr("G43 needs H<n> or a tool loaded by M6 (T<n> M6) before it")};
    modal->lengthTool = *modal->loadedTool;
    return {};
}

// A block LinuxCNC refuses while cutter compensation is on (interp_convert.cc: G28/G30, G53,
// tool changes, coordinate system and axis offset changes, canned cycles), with what to do.
QString refusedUnderComp(const ProgramBlock& b)
{
    const QString off = ProgramLine::tr("turn cutter compensation off (G40) before it");
    switch (b.kind) {
    case BlockKind::Home:
        return ProgramLine::tr("G28 with cutter compensation on: %1, as in LinuxCNC").arg(off);
    case BlockKind::ToolChange:
        return ProgramLine::tr("M6 with cutter compensation on: %1, as in LinuxCNC").arg(off);
    case BlockKind::DrillCycle:
        return ProgramLine::tr("a drilling cycle with cutter compensation on: %1").arg(off);
    case BlockKind::SetCoordinates:
    case BlockKind::AxisOffset:
    case BlockKind::AxisOffsetReset:
    case BlockKind::AxisOffsetSuspend:
    case BlockKind::AxisOffsetRestore:
        return ProgramLine::tr("%1 changes the offsets under cutter compensation: %2, as in "
                               "LinuxCNC")
            .arg(blockWord(b), off);
    default:
        break;
    }
    if (b.machineCoordinates)
        return ProgramLine::tr("G53 with cutter compensation on: %1, as in LinuxCNC").arg(off);
    if (b.inverseTime)
        return ProgramLine::tr("inverse time (G93) with cutter compensation is not supported: "
                               "use G94");
    return {};
}

// A drilling cycle's number `letter`: from this line, or (sticky) from the line before while
// the same cycle stays the motion mode; into *keep. *missing: neither has it.
const ProgramWord* cycleNumber(const Words& sorted, QChar letter, bool sticky,
                               std::optional<double>* keep, bool* missing)
{
    const ProgramWord* w = letter == QLatin1Char('Z') ? sorted.axes.value(QStringLiteral("Z"))
                                                      : sorted.parameters.value(letter);
    if (w)
        *keep = w->value;
    *missing = !w && (!sticky || !*keep);
    return w;
}

// Z, R, Q (G83, G73) and P (G82) of a drilling cycle into *modal, each checked.
std::pair<int, QString> cycleNumbers(const Words& sorted, int code, bool sticky, int column,
                                     ModalState* modal)
{
    const QString g = QStringLiteral("G%1").arg(code);
    const bool pecks = code == 83 || code == 73;
    struct Number
    {
        QChar letter;
        std::optional<double>* keep;
        bool used;
        QString need;
    };
    const Number numbers[] = {
        {QLatin1Char('Z'), &modal->cycleBottom, true, ProgramLine::tr("the hole's bottom")},
        {QLatin1Char('R'), &modal->cycleR, true, ProgramLine::tr("the retract plane")},
        {QLatin1Char('Q'), &modal->cyclePeck, pecks, ProgramLine::tr("the depth of each peck")},
        {QLatin1Char('P'), &modal->cycleDwell, code == 82,
         ProgramLine::tr("the dwell at the bottom in seconds")},
    };
    for (const Number& n : numbers) {
        if (!n.used) {
            if (const ProgramWord* unused = sorted.parameters.value(n.letter))
                return {unused->column,
                        ProgramLine::tr("%1 is not used by %2").arg(unused->valueText(), g)};
            continue;
        }
        bool missing = false;
        const ProgramWord* w = cycleNumber(sorted, n.letter, sticky, n.keep, &missing);
        if (missing)
            return {column, ProgramLine::tr("%1 needs %2: %3").arg(g, QString(n.letter), n.need)};
        const double v = **n.keep;
        if (n.letter == QLatin1Char('Q') && v <= 0)
            return {
                w ? w->column : column,
                ProgramLine::tr("%1: Q, the depth of each peck, must be greater than 0").arg(g)};
        if (n.letter == QLatin1Char('P') && (v < 0 || v > 1e6))
            return {w ? w->column : column,
                    ProgramLine::tr("%1: P must lie within 0..1000000 seconds").arg(g)};
    }
    return {};
}

} // namespace

// The line's modal words into *modal (G17-G19, G61/G64, G80, T, G90/G91, G20/G21, F).
std::pair<int, QString> applyModalWords(Words* words, ModalState* modal)
{
    if (words->plane)
        modal->plane = *words->plane;
    if (const auto [column, why] = applyPathMode(words, modal); column > 0)
        return {column, why};
    if (words->cancelsMotion)
        modal->motion.reset(); // G80: axis words need a motion word again (LinuxCNC)
    if (words->centreAbsolute)
        modal->centreAbsolute = *words->centreAbsolute;
    if (words->coordinateSystem)
        modal->coordinateSystem = *words->coordinateSystem;
    if (words->tool)
        modal->tool = int(words->tool->value);
    if (const auto [column, why] = applyLengthOffset(words, modal); column > 0)
        return {column, why};
    if (const auto [column, why] = applyCutterComp(words, modal); column > 0)
        return {column, why};
    if (words->relative)
        modal->relative = *words->relative;
    if (words->retractToR)
        modal->retractToR = *words->retractToR;
    if (words->inches)
        modal->inches = *words->inches;
    if (words->inverseTime) {
        // Leaving G93 for G94: F was a time, not a rate; G1 needs a new F (LinuxCNC sets the
        // feed rate to 0 at G94). G94 while in G94 keeps F (a deviation: LinuxCNC clears it
        // there too, which would refuse CAM headers that write F before G94).
        if (modal->inverseTime && !*words->inverseTime)
            modal->feed.reset();
        modal->inverseTime = *words->inverseTime;
    }
    if (const ProgramWord* s = words->parameters.value('S')) {
        if (s->value < 0 || s->value > 1e6)
            return {s->column,
                    ProgramLine::tr("%1 must lie within 0..1000000").arg(s->valueText())};
        modal->spindleSpeed = s->value;
    }
    if (const ProgramWord* f = words->parameters.value('F')) {
        if (f->value <= 0)
            return {
                f->column,
                ProgramLine::tr("%1: the feed rate must be greater than 0").arg(f->valueText())};
        modal->feed = f->value;
    }
    return {};
}

// G40, G41/G42 [D<tool>], G41.1/G42.1 D<diameter> (LinuxCNC, docs/programs.md "Cutter
// compensation"). G41 without D takes the tool the last M6 loaded (an M6 on this line counts);
// LinuxCNC would then compensate by 0 where no tool is loaded, which StepDeck refuses as G43 does.
std::pair<int, QString> applyCutterComp(Words* words, ModalState* modal)
{
    if (!words->cutterComp)
        return {};
    const int tenths = *words->cutterComp;
    const ProgramWord* g = words->groups.value(7);
    const ProgramWord* d = words->parameters.value('D');
    if (tenths == 400) { // G40; D stays and is refused as a word no action takes
        modal->comp = CutterComp{};
        return {};
    }
    if (modal->comp.on())
        return {g->column, ProgramLine::tr("%1: cutter compensation is on already: G40 first, as "
                                           "in LinuxCNC")
                               .arg(g->valueText())};
    if (modal->plane != Plane::XY)
        return {g->column, ProgramLine::tr("%1: cutter compensation works in the XY plane (G17) "
                                           "only")
                               .arg(g->valueText())};
    CutterComp comp;
    comp.side = tenths == 410 || tenths == 411 ? CompSide::Left : CompSide::Right;
    if (tenths % 10 == 1) { // G41.1, G42.1: D is the diameter
        if (!d)
            return {g->column,
                    ProgramLine::tr("%1 needs D: the tool's diameter").arg(g->valueText())};
        if (d->value < 0 || d->value > 1e6)
            return {
                d->column,
                ProgramLine::tr("%1: the diameter must lie within 0..1000000").arg(d->valueText())};
        comp.diameter = d->value;
    } else if (d) {
        if (!isWhole(d->value) || d->value < 0 || d->value > kMaxTool)
            return {d->column, ProgramLine::tr("%1: D takes a tool number, whole, 0..%2 (G41.1 "
                                               "D takes a diameter)")
                                   .arg(d->valueText())
                                   .arg(kMaxTool)};
        comp.tool = int(d->value);
    } else if (modal->loadedTool) {
        comp.tool = *modal->loadedTool;
    } else {
        return {g->column, ProgramLine::tr("%1 needs D<tool> or a tool loaded by M6 (T<n> M6) "
                                           "before it")
                               .arg(g->valueText())};
    }
    words->parameters.remove('D');
    comp.activation = ++modal->compActivations;
    modal->comp = comp;
    modal->compMove = ModalState::CompMove::Entry;
    return {};
}

std::pair<int, QString> checkCutterComp(const Words& words, const ModalState& before,
                                        ModalState* after, const std::vector<ProgramBlock>& blocks)
{
    if (before.comp.on() && !after->comp.on())
        after->compMove = ModalState::CompMove::Exit;
    if (before.comp.on() && after->comp.on()) {
        if (before.plane != after->plane)
            return {words.groups.value(2)->column,
                    ProgramLine::tr("the plane cannot change under cutter compensation: G40 "
                                    "first, as in LinuxCNC")};
        if (before.inches != after->inches)
            return {words.unitsWord ? words.unitsWord->column : 1,
                    ProgramLine::tr("the units cannot change under cutter compensation: G40 "
                                    "first, as in LinuxCNC")};
        if (before.coordinateSystem != after->coordinateSystem)
            return {words.groups.value(12)->column,
                    ProgramLine::tr("the coordinate system cannot change under cutter "
                                    "compensation: G40 first, as in LinuxCNC")};
    }
    for (const ProgramBlock& b : blocks) {
        const int column = b.actionColumn > 0 ? b.actionColumn : 1;
        if (b.comp.on())
            if (const QString why = refusedUnderComp(b); !why.isEmpty())
                return {column, why};
        const bool planeMove =
            isArc(b.kind) ||
            ((b.kind == BlockKind::Rapid || b.kind == BlockKind::Feed) &&
             (b.axes.contains(QStringLiteral("X")) || b.axes.contains(QStringLiteral("Y"))));
        const ModalState::CompMove pending = after->compMove;
        if (pending == ModalState::CompMove::None)
            continue;
        // LinuxCNC: after G40 the next move of any kind leaves the path; after G41/G42 the first
        // move in X or Y enters it.
        const bool leaves =
            pending == ModalState::CompMove::Exit &&
            (isArc(b.kind) || b.kind == BlockKind::Rapid || b.kind == BlockKind::Feed);
        if (!planeMove && !leaves)
            continue;
        if (isArc(b.kind))
            return {column,
                    pending == ModalState::CompMove::Entry
                        ? CutterCompensation::arcEntryRefusal(b)
                        : ProgramLine::tr("%1 leaves cutter compensation: the first move after "
                                          "G40 must be a straight line (G0 or G1), as in LinuxCNC")
                              .arg(blockWord(b))};
        after->compMove = ModalState::CompMove::None;
    }
    return {};
}

// G81, G82, G83, G73 (LinuxCNC, docs/programs.md "Drilling cycles"): the cycle's numbers into
// b->cycle and their sticky copies into *modal.
std::pair<int, QString> drillCycle(const Words& sorted, ModalState* modal, ProgramBlock* b)
{
    CycleWords& c = b->cycle;
    c.code = sorted.cycleCode > 0 ? sorted.cycleCode : modal->cycleCode;
    const QString g = QStringLiteral("G%1").arg(c.code);
    const bool sticky = modal->motion == BlockKind::DrillCycle && modal->cycleCode == c.code;
    const int column = sorted.actionWord ? sorted.actionWord->column : sorted.axes.first()->column;
    if (modal->plane != Plane::XY)
        return {column,
                ProgramLine::tr("%1: drilling cycles run in the XY plane (G17) only").arg(g)};
    for (auto it = sorted.axes.cbegin(); it != sorted.axes.cend(); ++it)
        if (it.key() != QLatin1String("X") && it.key() != QLatin1String("Y") &&
            it.key() != QLatin1String("Z"))
            return {it.value()->column,
                    ProgramLine::tr("%1: a drilling cycle moves X, Y and Z only, not %2")
                        .arg(g, it.key())};
    if (const auto [at, why] = cycleNumbers(sorted, c.code, sticky, column, modal); at > 0)
        return {at, why};
    c.bottom = *modal->cycleBottom;
    c.r = *modal->cycleR;
    c.peck = c.code == 83 || c.code == 73 ? *modal->cyclePeck : 0.0;
    c.dwell = c.code == 82 ? *modal->cycleDwell : 0.0;
    c.retractToR = modal->retractToR;
    if (const ProgramWord* l = sorted.parameters.value('L')) {
        if (!isWhole(l->value) || l->value < 1 || l->value > kMaxCycleRepeats)
            return {l->column, ProgramLine::tr("%1: L, the repeats, takes a whole number 1..%2")
                                   .arg(l->valueText())
                                   .arg(kMaxCycleRepeats)};
        c.repeats = int(l->value);
    }
    // LinuxCNC refuses a bottom above the retract plane (G91: Z is measured from R).
    if (modal->relative ? c.bottom > 0 : c.bottom > c.r)
        return {column,
                modal->relative
                    ? ProgramLine::tr("%1: in G91, Z is measured down from R: not above 0").arg(g)
                    : ProgramLine::tr("%1: Z%2 lies above R%3: the hole's bottom must lie "
                                      "below the retract plane")
                          .arg(g)
                          .arg(c.bottom)
                          .arg(c.r)};
    modal->motion = BlockKind::DrillCycle;
    modal->cycleCode = c.code;
    return {};
}

} // namespace stepdeck::program
