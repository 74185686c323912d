#include "NgcInterpreter.h"
#include <QDir>
#include <QFile>
#include <cmath>

namespace stepdeck::program {

struct NgcInterpreter::File
{
    QString path; // empty: the main file
    QStringList lines;
    NgcStructure structure;
};

struct NgcInterpreter::Frame
{
    const File* returnFile = nullptr;
    int returnPc = 0;
    int mapLine = 0; // the main file's line of the outermost call into a folder subroutine
    QHash<int, qint64> passes; // loop line -> passes since it was entered
    QHash<int, qint64> left;   // repeat line -> passes still to run
};

namespace {

// LinuxCNC's block delete over a file's lines before anything is read (NgcContext::blockDelete):
// on, a line whose first character is "/" becomes blank (the line numbers stay); off, the "/"
// becomes a space (the words keep their columns). The lines blanked; *first: the first (1-based).
int applyBlockDelete(QStringList* lines, bool on, int* first)
{
    int count = 0;
    for (qsizetype i = 0; i < lines->size(); ++i) {
        QString& line = (*lines)[i];
        qsizetype p = 0;
        while (p < line.size() && line.at(p).isSpace())
            ++p;
        if (p >= line.size() || line.at(p) != QLatin1Char('/'))
            continue;
        if (!on) {
            line[p] = QLatin1Char(' ');
            continue;
        }
        line.clear();
        if (count++ == 0 && first)
            *first = int(i) + 1;
    }
    return count;
}

} // namespace

NgcInterpreter::NgcInterpreter(const QStringList& lines, const NgcContext& context, Output output)
    : m_context(context), m_output(std::move(output)),
      m_parameters(context.coordinateSystems, context.activeSystem)
{
    auto main = std::make_unique<File>();
    main->lines = lines;
    m_deleted = applyBlockDelete(&main->lines, context.blockDelete, &m_firstDeleted);
    m_files.push_back(std::move(main));
    m_file = m_files.front().get();
    m_frames.push_back(Frame{});
}

NgcInterpreter::~NgcInterpreter() = default;

int NgcInterpreter::sourceLine() const
{
    return m_file == m_files.front().get() ? m_pc + 1 : m_frames.last().mapLine;
}

bool NgcInterpreter::fail(int column, const QString& message)
{
    if (m_error)
        return false;
    if (m_file == m_files.front().get()) {
        m_error = ProgramError{m_pc + 1, column, message};
    } else {
        m_error = ProgramError{sourceLine(), 1,
                               tr("%1:%2:%3: %4")
                                   .arg(QDir::toNativeSeparators(m_file->path))
                                   .arg(m_pc + 1)
                                   .arg(column)
                                   .arg(message)};
    }
    return false;
}

bool NgcInterpreter::failAt(const std::optional<ProgramError>& error)
{
    return fail(error ? error->column : 1, error ? error->message : tr("internal: no reason"));
}

bool NgcInterpreter::run(QList<ProgramError>* errors, int maxErrors)
{
    std::optional<NgcStructure> structure =
        NgcStructure::scan(m_files.front()->lines, errors, maxErrors);
    if (!structure)
        return false;
    m_files.front()->structure = std::move(*structure);
    while (!m_ended && !m_error) {
        if (m_pc >= m_file->lines.size()) {
            if (m_file == m_files.front().get())
                break;
            fail(1, tr("the subroutine's file ends before its endsub"));
            break;
        }
        // A long line counts once per 64 characters: the bound is on the work, not the lines.
        m_steps += 1 + m_file->lines.at(m_pc).size() / 64;
        if (m_steps > m_context.limits.steps) {
            fail(1, tr("the program runs more than %1 lines (a long line counts once per 64 "
                       "characters): a runaway loop? (the check stops there)")
                        .arg(m_context.limits.steps));
            break;
        }
        if (m_keepGoing && ++m_sinceAsked >= 4096) {
            m_sinceAsked = 0;
            if (!m_keepGoing()) {
                m_cancelled = true;
                return false;
            }
        }
        step();
    }
    if (m_error) {
        *errors << *m_error;
        return false;
    }
    return true;
}

bool NgcInterpreter::step()
{
    if (const NgcStatement* s = m_file->structure.statement(m_pc))
        return statement(*s);
    return ordinary(m_file->lines.at(m_pc));
}

bool NgcInterpreter::ordinary(const QString& text)
{
    std::optional<ProgramError> error;
    const std::optional<NgcExpandedLine> line =
        NgcLineExpander::expand(text, sourceLine(), m_parameters, &error);
    if (!line)
        return failAt(error);
    if (line->keep) {
        if (++m_lines > m_context.limits.lines)
            return fail(1, tr("the program gives out more than %1 lines to run: a runaway loop? "
                              "(the check stops there)")
                               .arg(m_context.limits.lines));
        QList<int> columns;
        if (m_file == m_files.front().get())
            for (const NgcExpandedLine::Word& w : line->words)
                columns << w.column;
        if (!m_output(line->text, sourceLine(), columns))
            return fail(1, tr("the worked-out program cannot be kept (see the log)"));
    }
    for (const NgcExpandedLine::Assignment& a : line->assignments) {
        if (a.target.number == 0) {
            if (a.target.name == QLatin1String("_value") ||
                a.target.name == QLatin1String("_value_returned") ||
                a.target.name == QLatin1String("_call_level"))
                return fail(a.target.column,
                            tr("#<%1> is LinuxCNC's, read-only").arg(a.target.name));
            m_parameters.setNamed(a.target.name, a.value);
            continue;
        }
        const QString why = m_parameters.setNumbered(a.target.number, a.value);
        if (!why.isEmpty())
            return fail(a.target.column, why);
    }
    for (int g = 54; g <= 59; ++g)
        if (line->has('G', g))
            m_parameters.noteSystem(g - 54);
    if (line->has('G', 10))
        m_parameters.noteOffsetsChanged(sourceLine());
    for (const double g : {92.0, 92.1, 92.2, 92.3})
        if (line->has('G', g))
            m_parameters.noteAxisOffsetChanged(sourceLine());
    noteInput(*line);
    // M2/M30 end the program; LinuxCNC reads nothing after them (subroutines after them are
    // found by their definition). A second "%" ends it likewise.
    if (line->has('M', 2) || line->has('M', 30))
        m_ended = true;
    if (text.trimmed() == QLatin1String("%")) {
        m_ended = m_percentOpen;
        m_percentOpen = true;
    }
    if (m_ended && m_frames.size() == 1) { // outside any call: where the lines not read start
        m_endLine = m_pc + 1;
        m_endedAtPercent = text.trimmed() == QLatin1String("%");
    }
    ++m_pc;
    return true;
}

int NgcInterpreter::unreadLines() const
{
    if (m_endLine <= 0)
        return 0;
    const File& main = *m_files.front();
    bool closing = m_percentOpen && !m_endedAtPercent; // the "%" after M2/M30 still to come
    int count = 0;
    for (int i = m_endLine; i < main.lines.size(); ++i) { // from the line after the end
        const NgcStatement* s = main.structure.statement(i);
        if (s && s->kind == NgcStatement::Sub) { // found there by its calls (LinuxCNC)
            const int end = main.structure.partner(i);
            if (end < i)
                break;
            i = end;
            continue;
        }
        const QString t = main.lines.at(i).trimmed();
        if (t.isEmpty())
            continue;
        if (closing && t == QLatin1String("%")) {
            closing = false;
            continue;
        }
        ++count;
    }
    return count;
}

// M66 in StepDeck waits for its input's state (L3 high, L4 low) and stops the run when Q runs
// out (docs/programs.md "Inputs and outputs"): a run that goes on past it has read 1 or 0.
// LinuxCNC's -1 (timed out) never reaches the next line, so the only path on is the checked one.
void NgcInterpreter::noteInput(const NgcExpandedLine& line)
{
    if (!line.has('M', 66))
        return;
    if (line.has('L', 3))
        m_parameters.noteInput(1.0, sourceLine());
    else if (line.has('L', 4))
        m_parameters.noteInput(0.0, sourceLine());
}

bool NgcInterpreter::statement(const NgcStatement& s)
{
    const NgcStructure& st = m_file->structure;
    switch (s.kind) {
    case NgcStatement::Sub:
        m_pc = st.partner(m_pc) + 1;
        return true; // a definition
    case NgcStatement::EndSub:
    case NgcStatement::Return:
        return leave(s);
    case NgcStatement::Call:
        return call(s);
    case NgcStatement::If:
        return branch(m_pc);
    case NgcStatement::ElseIf:
    case NgcStatement::Else:
        m_pc = st.endIf(m_pc) + 1;
        return true; // a branch ran
    case NgcStatement::EndIf:
        ++m_pc;
        return true;
    case NgcStatement::Break:
    case NgcStatement::Continue:
        return jumpOut(s);
    default:
        return loopStatement(s);
    }
}

// rest: an optional value, then at most a comment. *value: nullopt when there is none.
std::optional<double> NgcInterpreter::condition(const NgcStatement& s, bool required)
{
    const QString& text = m_file->lines.at(m_pc);
    qsizetype pos = s.rest;
    while (pos < text.size() && text.at(pos).isSpace())
        ++pos;
    const bool none =
        pos >= text.size() || text.at(pos) == QLatin1Char('(') || text.at(pos) == QLatin1Char(';');
    if (none) {
        if (required)
            fail(int(pos) + 1, tr("%1 needs a value: [ … ]").arg(s.name()));
        return std::nullopt;
    }
    NgcExpression e(text, m_parameters);
    e.setLineNumber(m_pc + 1);
    const std::optional<double> v = e.readValue(&pos);
    if (!v) {
        failAt(e.error());
        return std::nullopt;
    }
    while (pos < text.size() && text.at(pos).isSpace())
        ++pos;
    if (pos < text.size() && text.at(pos) != QLatin1Char('(') && text.at(pos) != QLatin1Char(';')) {
        fail(int(pos) + 1,
             tr("%1 takes one value; \"%2\" follows it").arg(s.name(), text.mid(pos)));
        return std::nullopt;
    }
    return v;
}

bool NgcInterpreter::branch(int line)
{
    const NgcStructure& st = m_file->structure;
    for (int b = line;;) {
        m_pc = b;
        const NgcStatement* s = st.statement(b);
        if (s->kind != NgcStatement::If && s->kind != NgcStatement::ElseIf) {
            m_pc = b + 1; // else (runs) or endif (nothing ran)
            return true;
        }
        const std::optional<double> c = condition(*s, true);
        if (!c)
            return false;
        if (*c != 0.0) {
            m_pc = b + 1;
            return true;
        }
        b = st.partner(b);
    }
}

bool NgcInterpreter::pass(const NgcStatement& s, int loop)
{
    if (++m_frames.last().passes[loop] <= m_context.limits.passes)
        return true;
    return fail(s.column, tr("%1 (line %2) has run %3 passes: a runaway loop? (the check stops a "
                             "loop there)")
                              .arg(m_file->structure.statement(loop)->name())
                              .arg(loop + 1)
                              .arg(m_context.limits.passes));
}

bool NgcInterpreter::loopStatement(const NgcStatement& s)
{
    const NgcStructure& st = m_file->structure;
    Frame& f = m_frames.last();
    switch (s.kind) {
    case NgcStatement::While:
    case NgcStatement::DoWhile: {
        const std::optional<double> c = condition(s, true);
        if (!c)
            return false;
        const int loop = s.kind == NgcStatement::While ? m_pc : st.partner(m_pc);
        if (*c == 0.0) {
            f.passes.remove(loop);
            m_pc = s.kind == NgcStatement::While ? st.partner(m_pc) + 1 : m_pc + 1;
            return true;
        }
        if (s.kind == NgcStatement::DoWhile) {
            m_pc = loop; // the do counts the pass
            return true;
        }
        return pass(s, m_pc) && (++m_pc, true);
    }
    case NgcStatement::EndWhile:
        m_pc = st.partner(m_pc);
        return true;
    case NgcStatement::Do:
        return pass(s, m_pc) && (++m_pc, true);
    case NgcStatement::Repeat:
        return repeat(s);
    case NgcStatement::EndRepeat: {
        const int r = st.partner(m_pc);
        if (--f.left[r] > 0) {
            m_pc = r + 1;
        } else {
            f.left.remove(r);
            ++m_pc;
        }
        return true;
    }
    default:
        return fail(s.column, tr("internal: %1 is not a loop statement").arg(s.name()));
    }
}

bool NgcInterpreter::repeat(const NgcStatement& s)
{
    const std::optional<double> n = condition(s, true);
    if (!n)
        return false;
    const double count = std::round(*n);
    if (std::fabs(*n - count) >= NgcExpression::kEqualTolerance || count < 0 ||
        count > double(m_context.limits.passes))
        return fail(s.column, tr("%1 needs a whole count from 0 to %2, got %3")
                                  .arg(s.name())
                                  .arg(m_context.limits.passes)
                                  .arg(*n));
    if (count == 0) {
        m_pc = m_file->structure.partner(m_pc) + 1;
        return true;
    }
    m_frames.last().left[m_pc] = qint64(count);
    ++m_pc;
    return true;
}

bool NgcInterpreter::jumpOut(const NgcStatement& s)
{
    const NgcStructure& st = m_file->structure;
    Frame& f = m_frames.last();
    const int loop = st.loopOf(m_pc);
    const int end = st.partner(loop);
    // The loops inside this one start afresh when they are entered again.
    const int from = s.kind == NgcStatement::Break ? loop : loop + 1;
    for (QHash<int, qint64>* state : {&f.passes, &f.left})
        for (auto it = state->begin(); it != state->end();)
            it = (it.key() >= from && it.key() <= end) ? state->erase(it) : std::next(it);
    if (s.kind == NgcStatement::Break) {
        m_pc = end + 1;
        return true;
    }
    // continue: a while tests again; a do's closing while tests; a repeat counts the pass.
    m_pc = st.statement(loop)->kind == NgcStatement::While ? loop : end;
    return true;
}

bool NgcInterpreter::call(const NgcStatement& s)
{
    const QString& text = m_file->lines.at(m_pc);
    QList<double> arguments;
    NgcExpression e(text, m_parameters);
    e.setLineNumber(m_pc + 1);
    for (qsizetype pos = s.rest;;) {
        while (pos < text.size() && text.at(pos).isSpace())
            ++pos;
        if (pos >= text.size() || text.at(pos) == QLatin1Char('(') ||
            text.at(pos) == QLatin1Char(';'))
            break;
        if (arguments.size() >= NgcParameters::kCallArguments)
            return fail(int(pos) + 1, tr("a call takes at most %1 arguments (#1..#%1)")
                                          .arg(NgcParameters::kCallArguments));
        const std::optional<double> v = e.readValue(&pos);
        if (!v)
            return failAt(e.error());
        arguments << *v;
    }
    if (m_parameters.callLevel() >= kMaxCallDepth)
        return fail(s.column, tr("%1: calls nest deeper than %2 (LinuxCNC's limit)")
                                  .arg(s.name())
                                  .arg(kMaxCallDepth));
    int line = -1;
    const File* file = findSubroutine(s.label, &line);
    if (!file) {
        if (!m_error)
            fail(s.column,
                 m_context.subroutineFolder.isEmpty() || s.label.at(0).isDigit()
                     ? tr("%1: the program has no %2 sub")
                           .arg(s.name(), NgcStatement::labelText(s.label))
                     : tr("%1: neither the program nor %2 has %3 sub")
                           .arg(s.name(),
                                QDir::toNativeSeparators(
                                    QDir(m_context.subroutineFolder).filePath(s.label + ".ngc")),
                                NgcStatement::labelText(s.label)));
        return false;
    }
    Frame frame;
    frame.returnFile = m_file;
    frame.returnPc = m_pc + 1;
    frame.mapLine = m_file == m_files.front().get() ? m_pc + 1 : m_frames.last().mapLine;
    m_frames.push_back(std::move(frame));
    m_parameters.enterCall(arguments);
    m_file = file;
    m_pc = line + 1;
    return true;
}

bool NgcInterpreter::leave(const NgcStatement& s)
{
    std::optional<double> value = condition(s, false);
    if (m_error)
        return false;
    if (m_frames.size() <= 1)
        return fail(s.column, tr("%1 outside a call").arg(s.name()));
    const Frame frame = m_frames.takeLast();
    m_parameters.leaveCall();
    m_parameters.setReturned(value);
    m_file = frame.returnFile;
    m_pc = frame.returnPc;
    return true;
}

// LinuxCNC: a subroutine the program defines, then <SUBROUTINE_PATH>/<name>.ngc.
const NgcInterpreter::File* NgcInterpreter::findSubroutine(const QString& label, int* line)
{
    for (const std::unique_ptr<File>& f : m_files) {
        *line = f->structure.subroutine(label);
        if (*line >= 0)
            return f.get();
    }
    if (m_context.subroutineFolder.isEmpty() || label.at(0).isDigit())
        return nullptr;
    const QString path = QDir(m_context.subroutineFolder).filePath(label + QStringLiteral(".ngc"));
    QFile in(path);
    if (!in.exists())
        return nullptr;
    if (!in.open(QIODevice::ReadOnly) || in.size() > kMaxSubroutineBytes) {
        fail(1,
             in.isOpen()
                 ? tr("%1 is larger than %2 bytes")
                       .arg(QDir::toNativeSeparators(path))
                       .arg(kMaxSubroutineBytes)
                 : tr("cannot read %1: %2").arg(QDir::toNativeSeparators(path), in.errorString()));
        return nullptr;
    }
    auto file = std::make_unique<File>();
    file->path = path;
    for (QString l : QString::fromUtf8(in.readAll()).split(QLatin1Char('\n'))) {
        if (l.endsWith(QLatin1Char('\r')))
            l.chop(1);
        file->lines << l;
    }
    applyBlockDelete(&file->lines, m_context.blockDelete, nullptr);
    QList<ProgramError> errors;
    std::optional<NgcStructure> structure = NgcStructure::scan(file->lines, &errors, 1);
    if (!structure) {
        const ProgramError e = errors.value(0);
        fail(1, tr("%1:%2:%3: %4")
                    .arg(QDir::toNativeSeparators(path))
                    .arg(e.line)
                    .arg(e.column)
                    .arg(e.message));
        return nullptr;
    }
    file->structure = std::move(*structure);
    *line = file->structure.subroutine(label);
    if (*line < 0) {
        fail(1, tr("%1 does not define O<%2> sub").arg(QDir::toNativeSeparators(path), label));
        return nullptr;
    }
    m_files.push_back(std::move(file));
    return m_files.back().get();
}

} // namespace stepdeck::program
