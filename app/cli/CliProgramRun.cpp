// `stepdeck-cli run PROGRAM`: a motion program on the machine (issue 20; docs/cli.md "run",
// docs/programs.md). Parsing and the M0 rule come before anything is opened; the check before
// anything moves; the run itself is program::ProgramRunner's.
#include "CliProgramRun.h"
#include "CliEventWait.h"
#include "CliFeedHold.h"
#include "CliMachineMotion.h"
#include "CliMachineRun.h"
#include "CliProgramOutput.h"
#include "CliText.h"
#include "model/NumberParsing.h"
#include "program/CanonText.h"
#include "program/ProgramParser.h"
#include "program/ProgramReader.h"
#include "program/WorkOffsetStore.h"
#include "program/language/ProgramExpansion.h"
#include <QFile>
#include <QFileInfo>
#include <QSocketNotifier>
#include <QTextStream>
#include <limits>
#include <memory>
#include <termios.h>
#include <unistd.h>

namespace stepdeck::cli {

using program::Program;
using program::ProgramRunner;
using program::RunState;

namespace {
constexpr qint64 kReadChunk = 64 * 1024;
constexpr int kAbortSettleMs = 5000; // bound for the axes to stand after an abort

struct RunRequest
{
    QString path;
    int fromLine = 1;
    bool dryRun = false;
    bool canon = false; // --canon: the motion commands as rs274 prints them (issue 49)
    bool skipPauses = false;
    bool optionalStops = true; // M1 holds like M0 (ProgramRunner::setOptionalStops)
    // LinuxCNC's block delete: "/" lines skipped (ProgramParser::setBlockDelete); read with the
    // file, so the run runs what the check read.
    bool blockDelete = true;
    int feedOverride = 100; // percent (ProgramRunner::setFeedOverride)
    // The window keeps these per machine; the CLI takes them per call (issue 29).
    program::ToolTable tools;           // --tool-table FILE (LinuxCNC's tool.tbl)
    program::CoordinateSystems systems; // --offsets "G54:X=10,Y=5;G55:X=20" (G54 active)
    int activeSystem = 0;               // 0 = G54
    bool reference = false;             // --reference: every axis first, in the file's order
};

// "G54:X=10,Y=5;G55:X=20": each system's work zero per axis, in the axis' unit; axes the machine
// lacks are named. Empty: the text is fine.
QString parseOffsets(const QString& text, const machine::MachineDescription& d,
                     program::CoordinateSystems* out)
{
    for (const QString& part : text.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const int colon = int(part.indexOf(QLatin1Char(':')));
        const QString word = part.left(colon).trimmed().toUpper();
        int system = -1;
        for (int i = 0; i < program::kCoordinateSystems; ++i)
            if (word == program::coordinateSystemWord(i))
                system = i;
        if (colon < 0 || system < 0)
            return CliText::tr("--offsets: '%1' does not start with G54..G59 and a colon")
                .arg(part.trimmed());
        for (const QString& pair :
             part.mid(colon + 1).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            const QStringList kv = pair.split(QLatin1Char('='));
            double value = 0;
            if (kv.size() != 2 || !d.axis(kv.at(0).trimmed()) ||
                numbers::parseReal(kv.at(1).trimmed(), &value) != NumberError::None)
                return CliText::tr("--offsets: '%1' is not AXIS=NUMBER for an axis of the machine")
                    .arg(pair.trimmed());
            (*out)[size_t(system)].insert(kv.at(0).trimmed(), value);
        }
    }
    return {};
}

// Without --offsets, a machine file's work offsets as the window keeps them (issue 47 item 16:
// a CAM file runs in the coordinates the window shows), said on stderr.
void takeWindowOffsets(const CliOptions& o, RunRequest* r)
{
    if (o.machineFile.isEmpty())
        return;
    const program::StoredOffsets stored = program::WorkOffsetStore::load(
        *program::WorkOffsetStore::windowSettings(), QFileInfo(o.machineFile).absoluteFilePath());
    if (stored.isEmpty())
        return;
    r->systems = stored.systems;
    r->activeSystem = stored.active;
    QStringList systems;
    for (int i = 0; i < program::kCoordinateSystems; ++i) {
        QStringList axes;
        const QMap<QString, double>& s = stored.systems[size_t(i)];
        for (auto it = s.cbegin(); it != s.cend(); ++it)
            axes << QStringLiteral("%1=%2").arg(it.key()).arg(it.value());
        if (!axes.isEmpty() || i == stored.active)
            systems << QStringLiteral("%1:%2").arg(program::coordinateSystemWord(i),
                                                   axes.join(QLatin1Char(',')));
    }
    printError(
        CliText::tr("work offsets as the window keeps them for this machine: %1 (%2 "
                    "active; --offsets overrides)")
            .arg(systems.join(QLatin1Char(';')), program::coordinateSystemWord(stored.active)));
}

// --tool-table and --offsets, which need the machine's axes; exit 12 for an unreadable file.
Outcome readTablesArguments(const CliOptions& o, const machine::MachineDescription& d,
                            RunRequest* r)
{
    if (const std::optional<QString> offsets = o.value("offsets")) {
        if (const QString why = parseOffsets(*offsets, d, &r->systems); !why.isEmpty())
            return Outcome::usage(why);
    } else {
        takeWindowOffsets(o, r);
    }
    const std::optional<QString> path = o.value("tool-table");
    if (!path)
        return Outcome::success();
    QFile file(*path);
    if (!file.open(QIODevice::ReadOnly))
        return Outcome::failure(ExitFile, CliText::tr("cannot read %1").arg(*path));
    QList<program::ProgramError> errors;
    const std::optional<program::ToolTable> tools =
        program::ToolTable::parse(file.readAll(), &errors);
    if (!tools) {
        printProgramErrors(*path, errors);
        return Outcome::failure(ExitInvalidValue,
                                CliText::tr("%1 is not a tool table; nothing was sent").arg(*path));
    }
    r->tools = *tools;
    return Outcome::success();
}

Outcome parseRunArguments(const CliOptions& o, RunRequest* r)
{
    if (o.args.size() != 1)
        return Outcome::usage(
            CliText::tr("run needs one PROGRAM file (run PROGRAM [--dry-run [--canon]] "
                        "[--from-line N] [--skip-pauses] "
                        "[--optional-stops on|off] [--block-delete on|off] "
                        "[--feed-override PERCENT] "
                        "[--tool-table FILE] [--offsets G54:X=N,...;G55:...] "
                        "[--reference])"));
    r->path = o.args.constFirst();
    r->dryRun = o.flag("dry-run");
    r->canon = o.flag("canon");
    if (r->canon && !r->dryRun)
        return Outcome::usage(CliText::tr("run --canon needs --dry-run"));
    r->reference = o.flag("reference");
    r->skipPauses = o.flag("skip-pauses");
    if (const std::optional<QString> stops = o.value("optional-stops")) {
        if (*stops != QLatin1String("on") && *stops != QLatin1String("off"))
            return Outcome::usage(
                CliText::tr("run --optional-stops takes on or off, got '%1'").arg(*stops));
        r->optionalStops = *stops == QLatin1String("on");
    }
    if (const std::optional<QString> skip = o.value("block-delete")) {
        if (*skip != QLatin1String("on") && *skip != QLatin1String("off"))
            return Outcome::usage(
                CliText::tr("run --block-delete takes on or off, got '%1'").arg(*skip));
        r->blockDelete = *skip == QLatin1String("on");
    }
    if (const std::optional<QString> feed = o.value("feed-override");
        feed && numbers::parseInt(*feed, 10, 200, &r->feedOverride) != NumberError::None)
        return Outcome::usage(
            CliText::tr("run --feed-override takes a percentage 10..200, got '%1'").arg(*feed));
    if (const std::optional<QString> from = o.value("from-line");
        from && numbers::parseInt(*from, 1, std::numeric_limits<int>::max(), &r->fromLine) !=
                    NumberError::None)
        return Outcome::usage(
            CliText::tr("run --from-line needs a line number (1 or more), got '%1'").arg(*from));
    return Outcome::success();
}

// A program in LinuxCNC's language (issue 33): worked out against the run's offsets and the
// machine's subroutine folder, then parsed; its blocks name the file's lines.
Outcome readWorkedOut(const RunRequest& r, const machine::MachineDescription& d,
                      const QStringList& axisNames, Program* out)
{
    program::NgcContext context;
    context.coordinateSystems = r.systems;
    context.activeSystem = r.activeSystem;
    context.subroutineFolder = d.subroutineFolderPath;
    context.blockDelete = r.blockDelete;
    QList<program::ProgramError> errors;
    const std::optional<program::ProgramExpansion::Result> expanded =
        program::ProgramExpansion::expand(program::ProgramSource::file(r.path), context, &errors);
    std::optional<Program> parsed;
    if (expanded) {
        program::ProgramReader reader(expanded->source, axisNames, expanded->info->lines);
        parsed = reader.finish(&errors);
    }
    if (!parsed) {
        printProgramErrors(r.path, errors);
        return Outcome::failure(
            ExitInvalidValue,
            CliText::tr("%1 is not a valid program; nothing was sent").arg(r.path));
    }
    parsed->expansion = expanded->info;
    *out = *parsed;
    return Outcome::success();
}

// The whole file through the streaming parser, before any link is opened: exit 12 when it
// cannot be read, 7 with every FILE:LINE:COL error.
Outcome readProgram(const RunRequest& r, const machine::MachineDescription& d, Program* out)
{
    QFile file(r.path);
    if (!QFileInfo(r.path).isFile() || !file.open(QIODevice::ReadOnly))
        return Outcome::failure(ExitFile, CliText::tr("cannot read %1").arg(r.path));
    QStringList axisNames;
    for (const machine::MachineAxis& a : d.axes)
        axisNames << a.name;
    QString why;
    const std::optional<bool> language =
        program::ProgramExpansion::usesLanguage(program::ProgramSource::file(r.path), &why);
    if (!language)
        return Outcome::failure(ExitFile, CliText::tr("cannot read %1: %2").arg(r.path, why));
    if (*language)
        return readWorkedOut(r, d, axisNames, out);
    // Streamed (issue 29): only the parser's index stays in memory, whatever the length.
    program::ProgramParser parser(axisNames);
    parser.setBlockDelete(r.blockDelete);
    TerminalProgress progress(CliText::tr("reading %1").arg(r.path));
    const qint64 size = file.size();
    while (!file.atEnd()) {
        const QByteArray chunk = file.read(kReadChunk);
        if (chunk.isEmpty() && file.error() != QFileDevice::NoError)
            return Outcome::failure(
                ExitFile, CliText::tr("cannot read %1: %2").arg(r.path, file.errorString()));
        parser.feed(chunk);
        progress.update(file.pos(), size);
    }
    progress.done();
    QList<program::ProgramError> errors;
    std::optional<Program> parsed = parser.finish(&errors);
    if (!parsed) {
        printProgramErrors(r.path, errors);
        return Outcome::failure(
            ExitInvalidValue,
            CliText::tr("%1 is not a valid program; nothing was sent").arg(r.path));
    }
    parsed->source = program::ProgramSource::file(r.path);
    *out = *parsed;
    return Outcome::success();
}

// Tool lengths by touch-off (issue 50 item 4): an M6 of another tool than the run's M6 before it
// holds until the work Z is set for that tool, which the CLI cannot do (no position display, no
// MDI while a program runs), so such a run is refused before anything is opened, whatever would
// answer the prompts (a terminal, --skip-pauses). The run's first M6, and an M6 of the tool the
// one before it loaded, go on with the work Z as it is (ProgramRunner::resumeSameTool): as the
// window's Keep Z, on Enter or with --skip-pauses, for a shop that touched off before the run.
Outcome refuseTouchOffs(const Program& p, const RunRequest& r, const machine::MachineDescription& d)
{
    if (r.dryRun || d.toolLength != machine::ToolLength::TouchOff ||
        !d.axis(program::ProgramCoordinates::toolAxis()))
        return Outcome::success();
    program::ProgramReader reader(p);
    std::optional<int> before;
    for (int i = std::max(0, reader.firstBlockAtLine(r.fromLine));
         const program::ProgramBlock* at = reader.at(i); ++i) {
        if (at->kind != program::BlockKind::ToolChange)
            continue;
        if (before && *before != at->number)
            return Outcome::usage(
                CliText::tr("run: line %1 holds M6 \"%2\" with tool lengths by touch-off (the "
                            "machine file's toolLength): the run would wait there until the "
                            "work Z is set for tool %3, which the CLI cannot do; run it in the "
                            "window, or from the line after it (--from-line) once Z is set for "
                            "tool %3")
                    .arg(QString::number(at->line), at->prompt, QString::number(at->number)));
        before = at->number;
    }
    return Outcome::success();
}

// M0 (M6, and M1 with optional stops on) waits for Enter on a terminal; without one it would wait
// forever or read a script's input as the operator's, so such a run is refused before anything is
// opened.
Outcome refusePausesWithoutTerminal(const Program& p, const RunRequest& r)
{
    if (r.dryRun || r.skipPauses || ::isatty(STDIN_FILENO))
        return Outcome::success();
    program::ProgramReader reader(p);
    for (int i = std::max(0, reader.firstBlockAtLine(r.fromLine));
         const program::ProgramBlock* at = reader.at(i); ++i) {
        const program::ProgramBlock& b = *at;
        if (!program::waitsForOperator(b.kind, r.optionalStops))
            continue;
        if (b.kind == program::BlockKind::OptionalPause)
            return Outcome::usage(CliText::tr("run: line %1 holds M1, which waits for Enter on a "
                                              "terminal with optional stops on, and stdin is not "
                                              "one (--optional-stops off passes it, --skip-pauses "
                                              "runs on without stopping)")
                                      .arg(b.line));
        // An M6 names its tool and the line's comment ("Load tool 2 (6 mm end mill)").
        const QString what = b.kind == program::BlockKind::ToolChange
                                 ? QStringLiteral("M6 \"%1\"").arg(b.prompt)
                                 : program::blockWord(b.kind);
        return Outcome::usage(CliText::tr("run: line %1 holds %2, which waits for Enter on a "
                                          "terminal, and stdin is not one (--skip-pauses "
                                          "runs on without stopping there)")
                                  .arg(b.line)
                                  .arg(what));
    }
    return Outcome::success();
}

// At M0: on at once with --skip-pauses, else the prompt on stderr and on with Enter. Stdin
// closed (Ctrl-D) while waiting stops the program.
class PauseAnswer
{
public:
    PauseAnswer(ProgramRunner& runner, CliMachineSession& m, const CliFeedHold& hold, bool skip,
                bool json)
        : m_runner(runner), m_session(m), m_hold(hold), m_skip(skip), m_json(json)
    {
        QObject::connect(&runner, &ProgramRunner::paused, &m_guard,
                         [this](int line, const QString& prompt) { paused(line, prompt); });
        QObject::connect(&runner, &ProgramRunner::resumeRefused, &m_guard,
                         [this](const QString& message) {
                             if (!m_json)
                                 printProgress(message);
                         });
    }
    bool stdinClosed() const { return m_closed; }

private:
    void paused(int line, const QString& prompt)
    {
        if (m_hold.holding())
            return; // the operator's Ctrl-Z: SIGCONT resumes (CliFeedHold)
        const bool touchOff = m_runner.awaitsTouchOff();
        if (m_skip) {
            if (!m_json)
                printProgress(touchOff
                                  ? CliText::tr("line %1: tool change passed with the work Z "
                                                "as it is (--skip-pauses)")
                                        .arg(line)
                                  : CliText::tr("line %1: pause passed (--skip-pauses)").arg(line));
            // Not from inside the runner's own signal.
            QMetaObject::invokeMethod(
                &m_guard, [this] { goOn(); }, Qt::QueuedConnection);
            return;
        }
        // Only an Enter pressed after the prompt answers it: typed-ahead lines are dropped.
        ::tcflush(STDIN_FILENO, TCIFLUSH);
        printProgress(
            touchOff ? CliText::tr("line %1: %2 -- the CLI cannot set a work Z: Enter goes on "
                                   "with Z as it is, for the tool it was set for (Ctrl-C stops)")
                           .arg(QString::number(line), prompt)
            : prompt.isEmpty()
                ? CliText::tr("line %1: paused; press Enter to go on (Ctrl-C stops)").arg(line)
                : CliText::tr("line %1: %2 -- press Enter to go on (Ctrl-C stops)")
                      .arg(line)
                      .arg(prompt));
        if (!m_notifier) {
            m_notifier = std::make_unique<QSocketNotifier>(STDIN_FILENO, QSocketNotifier::Read);
            QObject::connect(m_notifier.get(), &QSocketNotifier::activated, &m_guard,
                             [this] { readAnswer(); });
        }
        m_notifier->setEnabled(true);
    }
    void readAnswer()
    {
        char buffer[256];
        const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (n > 0 && !QByteArray(buffer, int(n)).contains('\n'))
            return; // a line typed so far; Enter ends it
        m_notifier->setEnabled(false);
        if (m_runner.state() != RunState::Paused)
            return;
        if (n > 0) {
            goOn();
        } else {
            m_closed = true;
            m_runner.abort();
        }
        m_session.wake();
    }

    // On from the hold. A touch-off M6 goes on with the work Z as it is: refuseTouchOffs let only
    // those through where that is offered (the run's first M6, the same tool again).
    void goOn()
    {
        if (!m_runner.awaitsTouchOff())
            m_runner.resume();
        else if (!m_runner.resumeSameTool())
            m_runner.abort(); // not offered after all: the CLI cannot set a Z (said above)
    }

    ProgramRunner& m_runner;
    CliMachineSession& m_session;
    const CliFeedHold& m_hold;
    bool m_skip = false;
    bool m_json = false;
    bool m_closed = false;
    std::unique_ptr<QSocketNotifier> m_notifier;
    QObject m_guard;
};

Outcome dryRun(CliMachineSession& m, const Program& p, const RunRequest& r, bool json)
{
    program::MachineFacts facts = program::factsOf(m.machine());
    facts.coordinateSystems = r.systems;
    facts.activeSystem = r.activeSystem;
    facts.tools = r.tools;
    facts.blockDelete = r.blockDelete; // the program read with it already
    TerminalProgress progress(CliText::tr("checking %1").arg(r.path));
    // --canon: each motion command as the check's walk lowers it, streamed (a long program's
    // commands are never all held).
    QTextStream out(stdout);
    program::CanonText canon(m.description());
    motion::CommandSink lowered;
    if (r.canon)
        lowered = [&out, &canon](const motion::MotionCommand& c) {
            for (const QString& line : canon.lines(c))
                out << line << '\n';
        };
    const program::ProgramCheckResult checked =
        program::ProgramCheck::check(p, facts, r.fromLine, progress.callback(), lowered);
    out.flush();
    progress.done();
    if (!checked.ok()) {
        printProgramErrors(r.path, checked.errors);
        return Outcome::failure(
            ExitInvalidValue,
            CliText::tr("%1 cannot run on this machine; nothing was sent").arg(r.path));
    }
    if (r.canon)
        return Outcome::success();
    printProgramNotes(r.path, checked.notes, json); // issue 50: what runs otherwise, not refused
    printProgramPreview(r.path, checked.preview, m.description(), json);
    return Outcome::success();
}

// How a run that ended without an interrupt ends the command.
Outcome endOutcome(CliMachineSession& m, const ProgramRunner& runner, const PauseAnswer& pauses)
{
    switch (runner.state()) {
    case RunState::Finished:
        return Outcome::success();
    case RunState::Failed:
        if (m.linkLost())
            return Outcome::failure(ExitLinkDown, runner.endMessage());
        if (runner.failureKind() != ErrorKind::None) {
            // Exit 7 says "nothing was sent" (docs/cli.md): a value refused once the run has
            // started is a block refused by a rule, 3, whatever ran before it (issue 28).
            const int code = exitCodeFor(runner.failureKind());
            return Outcome::failure(code == ExitInvalidValue ? ExitRefused : code,
                                    runner.endMessage());
        }
        // A move the machine ended as failed may reach the runner before the request result
        // that says why: the session's last failed request tells (as for `move`), else the
        // move ended short (exit 13).
        return m.motionFailure(runner.endMessage());
    default:
        break;
    }
    if (pauses.stdinClosed())
        return Outcome::failure(
            ExitFailure, CliText::tr("stdin was closed at M0 (line %1): the program was stopped")
                             .arg(runner.currentLine()));
    return Outcome::failure(ExitFailure, runner.endMessage());
}

Outcome runProgram(CliMachineSession& m, const Program& p, const RunRequest& r, bool json)
{
    ProgramRunner runner(&m.machine());
    ProgramReport report(runner, p.expansion ? p.expansion->sourceLines : p.lines, json);
    runner.setOptionalStops(r.optionalStops);
    runner.setFeedOverride(r.feedOverride);
    runner.setCoordinateSystems(r.systems, r.activeSystem);
    runner.setToolTable(r.tools);
    CliFeedHold feedHold(runner, m, json);
    PauseAnswer pauses(runner, m, feedHold, r.skipPauses, json);
    CliEventWait settle; // after an interrupt, when the session's own waits return at once
    QObject guard;
    QObject::connect(&runner, &ProgramRunner::stateChanged, &guard, [&m, &settle] {
        m.wake();
        settle.wake();
    });
    QList<program::ProgramError> errors;
    TerminalProgress progress(CliText::tr("checking %1").arg(r.path));
    runner.setCheckProgress(progress.callback());
    const bool started = runner.start(p, r.fromLine, &errors);
    progress.done();
    if (!started) {
        printProgramErrors(r.path, errors);
        return Outcome::failure(
            ExitInvalidValue,
            CliText::tr("%1 cannot run on this machine; nothing was sent").arg(r.path));
    }
    printProgramNotes(r.path, runner.checkNotes(), json); // the run's check (issue 50)
    m.waitFor([&runner] { return program::isEnded(runner.state()); }, -1);
    Outcome outcome;
    if (m.interrupted()) {
        // The machine stops every controller and aborts the run that holds its motion
        // (Machine::abortRequested, as the window's STOP); the caller's stopAll() then reports
        // whether each acknowledged it (as for every command).
        const int line = runner.currentLine();
        m.machine().stop();
        const bool never = false;
        settle.waitFor([&runner] { return program::isEnded(runner.state()); }, kAbortSettleMs,
                       never);
        outcome =
            Outcome::failure(ExitInterrupted, CliText::tr("interrupted at line %1").arg(line));
    } else {
        outcome = endOutcome(m, runner, pauses);
    }
    report.summary(outcome, machinePositionsLine(m));
    return outcome;
}
} // namespace

Outcome machineRunProgram(CliMachineSession& m, const CliOptions& o)
{
    RunRequest r;
    if (Outcome parsed = parseRunArguments(o, &r); !parsed.ok())
        return parsed;
    if (Outcome tables = readTablesArguments(o, m.description(), &r); !tables.ok())
        return tables;
    Program p;
    if (Outcome read = readProgram(r, m.description(), &p); !read.ok())
        return read;
    if (r.fromLine > (p.expansion ? p.expansion->sourceLines : p.lines))
        return Outcome::usage(CliText::tr("run --from-line %1: %2 has %3 lines")
                                  .arg(r.fromLine)
                                  .arg(r.path)
                                  .arg(p.expansion ? p.expansion->sourceLines : p.lines));
    if (Outcome touchOff = refuseTouchOffs(p, r, m.description()); !touchOff.ok())
        return touchOff;
    if (Outcome allowed = refusePausesWithoutTerminal(p, r); !allowed.ok())
        return allowed;
    if (Outcome connected = m.connectAll(); !connected.ok())
        return connected;
    if (r.reference && !r.dryRun) {
        // Every axis in the file's order and directions (as `home` without axes), before the
        // check: an ordinary CAM file runs without a G28 of its own.
        QString refusal;
        const quint64 id = m.machine().reference({}, &refusal);
        if (id == 0)
            return Outcome::failure(
                ExitRefused,
                CliText::tr("run --reference refused, nothing was sent: %1").arg(refusal));
        if (Outcome done =
                machinemotion::waitMotion(m, &machine::Machine::referenceFinished, id, -1);
            !done.ok())
            return done;
    }
    return r.dryRun ? dryRun(m, p, r, o.json) : runProgram(m, p, r, o.json);
}

} // namespace stepdeck::cli
