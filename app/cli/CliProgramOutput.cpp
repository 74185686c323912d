// What `stepdeck-cli run` prints (docs/cli.md "run").
#include "CliProgramOutput.h"
#include "CliText.h"
#include <QJsonArray>
#include <QJsonObject>
#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace stepdeck::cli {

using program::ProgramRunner;
using program::RunState;

namespace {
// The states of a run as --json names them (fixed words: scripts compare them).
QString runStateKey(RunState state)
{
    switch (state) {
    case RunState::Idle:
        return QStringLiteral("idle");
    case RunState::Running:
        return QStringLiteral("running");
    case RunState::Paused:
        return QStringLiteral("paused");
    case RunState::Stopping:
        return QStringLiteral("stopping");
    case RunState::Finished:
        return QStringLiteral("finished");
    case RunState::Failed:
        return QStringLiteral("failed");
    case RunState::Aborted:
        return QStringLiteral("aborted");
    }
    return {};
}

QString number(double value)
{
    return QString::number(value, 'f', 3);
}

QString durationText(double seconds)
{
    if (seconds < 60)
        return CliText::tr("%1 s").arg(QString::number(seconds, 'f', 1));
    const qint64 whole = qint64(seconds + 0.5);
    return CliText::tr("%1 min %2 s").arg(whole / 60).arg(whole % 60);
}
} // namespace

void printProgress(const QString& line)
{
    const QByteArray bytes = (line.simplified() + QLatin1Char('\n')).toUtf8();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stderr);
    std::fflush(stderr);
}

TerminalProgress::TerminalProgress(const QString& what)
    : m_what(what), m_terminal(::isatty(STDERR_FILENO) != 0)
{}

TerminalProgress::~TerminalProgress()
{
    done();
}

bool TerminalProgress::update(qint64 done, qint64 total)
{
    if (!m_terminal || total <= 0)
        return true;
    const int percent = int(std::clamp<qint64>(done * 100 / total, 0, 100));
    if (percent == m_shown)
        return true;
    m_shown = percent;
    const QByteArray bytes =
        (QLatin1Char('\r') + CliText::tr("%1: %2 %").arg(m_what).arg(percent)).toUtf8();
    std::fwrite(bytes.constData(), 1, size_t(bytes.size()), stderr);
    std::fflush(stderr);
    return true;
}

program::CheckProgress TerminalProgress::callback()
{
    return [this](qint64 done, qint64 total) { return update(done, total); };
}

void TerminalProgress::done()
{
    if (m_shown < 0)
        return;
    m_shown = -1;
    // Erase the line: what follows starts at the left margin.
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
}

void printProgramErrors(const QString& path, const QList<program::ProgramError>& errors)
{
    for (const program::ProgramError& e : errors)
        printProgress(QStringLiteral("%1:%2").arg(path, e.text()));
}

void printProgramNotes(const QString& path, const QList<program::ProgramError>& notes, bool json)
{
    for (const program::ProgramError& n : notes) {
        if (json)
            printJson(QJsonObject{
                {"event", "note"}, {"line", n.line}, {"column", n.column}, {"message", n.message}});
        else
            printProgress(
                CliText::tr("%1:%2:%3: note: %4")
                    .arg(path, QString::number(n.line), QString::number(n.column), n.message));
    }
}

void printProgramPreview(const QString& path, const program::ProgramPreview& preview,
                         const machine::MachineDescription& description, bool json)
{
    if (json) {
        QJsonObject extents;
        for (auto it = preview.extents.cbegin(); it != preview.extents.cend(); ++it) {
            const machine::MachineAxis* axis = description.axis(it.key());
            extents.insert(it.key(),
                           QJsonObject{{"minimum", it->minimum},
                                       {"maximum", it->maximum},
                                       {"moved", it->moved},
                                       {"unit", axis ? machine::unitKey(axis->unit) : QString()}});
        }
        printJson(QJsonObject{{"event", "preview"},
                              {"lines", preview.lines},
                              {"blocks", preview.blocksRun},
                              {"estimatedSeconds", preview.estimatedSeconds},
                              {"extents", extents},
                              {"motion", preview.motionNote},
                              {"tools", preview.toolNote}});
        return;
    }
    printLine(CliText::tr("%1: %2 lines, %3 blocks to run")
                  .arg(path)
                  .arg(preview.lines)
                  .arg(preview.blocksRun));
    for (const machine::MachineAxis& axis : description.axes) {
        const auto it = preview.extents.constFind(axis.name);
        const QString unit = machine::unitKey(axis.unit);
        if (it == preview.extents.cend())
            printLine(CliText::tr("  %1: position unknown").arg(axis.name));
        else if (!it->moved)
            printLine(
                CliText::tr("  %1: not moved (%2 %3)").arg(axis.name, number(it->minimum), unit));
        else
            printLine(CliText::tr("  %1: %2 .. %3 %4")
                          .arg(axis.name, number(it->minimum), number(it->maximum), unit));
    }
    printLine(CliText::tr("estimated duration: %1 (estimated: known rates, no acceleration)")
                  .arg(durationText(preview.estimatedSeconds)));
    if (!preview.motionNote.isEmpty())
        printLine(preview.motionNote);
    if (!preview.toolNote.isEmpty()) // tool lengths by touch-off (issue 50 item 4)
        printLine(preview.toolNote);
}

ProgramReport::ProgramReport(ProgramRunner& runner, int lines, bool json)
    : m_runner(runner), m_lines(lines), m_json(json)
{
    m_clock.start();
    QObject::connect(&runner, &ProgramRunner::blockStarted, &m_guard,
                     [this](int line, const QString& text) { blockStarted(line, text); });
    QObject::connect(&runner, &ProgramRunner::blockFinished, &m_guard,
                     [this](int line) { blockFinished(line); });
    QObject::connect(&runner, &ProgramRunner::paused, &m_guard,
                     [this](int line, const QString& prompt) { paused(line, prompt); });
    QObject::connect(
        &runner, &ProgramRunner::operatorMessage, &m_guard, [this](int line, const QString& text) {
            if (m_json)
                printJson(QJsonObject{{"event", "message"}, {"line", line}, {"text", text}});
            else
                printProgress(CliText::tr("line %1: MSG: %2").arg(line).arg(text));
        });
    QObject::connect(&runner, &ProgramRunner::stopping, &m_guard, [this](const QString& message) {
        if (m_json)
            printJson(QJsonObject{{"event", "stopping"}, {"message", message}});
        else
            printProgress(message);
    });
}

void ProgramReport::blockStarted(int line, const QString& text)
{
    m_line = line;
    m_text = text;
    if (!m_json)
        printProgress(CliText::tr("line %1/%2: %3").arg(line).arg(m_lines).arg(text));
}

void ProgramReport::blockFinished(int line)
{
    if (m_json)
        printJson(QJsonObject{{"event", "block"},
                              {"line", line},
                              {"text", line == m_line ? m_text : QString()},
                              {"state", "done"},
                              {"blocksDone", m_runner.blocksDone()},
                              {"seconds", m_clock.elapsed() / 1000.0}});
}

void ProgramReport::paused(int line, const QString& prompt)
{
    if (m_json)
        printJson(QJsonObject{{"event", "paused"}, {"line", line}, {"prompt", prompt}});
}

void ProgramReport::summary(const Outcome& outcome, const QString& positions)
{
    const RunState state = m_runner.state();
    const double seconds = m_clock.elapsed() / 1000.0;
    if (m_json) {
        // The block a failed or stopped run ended at, as a block event of its own.
        if (!outcome.ok() && m_line > 0)
            printJson(QJsonObject{{"event", "block"},
                                  {"line", m_line},
                                  {"text", m_text},
                                  {"state", runStateKey(state)},
                                  {"message", outcome.message}});
        printJson(QJsonObject{{"event", "summary"},
                              {"state", runStateKey(state)},
                              {"exitCode", outcome.code},
                              {"line", outcome.ok() ? 0 : m_line},
                              {"blocksDone", m_runner.blocksDone()},
                              {"seconds", seconds},
                              {"message", outcome.message}});
        return;
    }
    if (outcome.ok())
        printLine(CliText::tr("finished: %1 blocks in %2; %3")
                      .arg(m_runner.blocksDone())
                      .arg(durationText(seconds), positions));
}

} // namespace stepdeck::cli
