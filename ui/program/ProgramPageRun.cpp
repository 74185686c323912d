// ProgramPage, part 2: running the program through the ProgramRunner and showing how the run
// goes (running line, progress, estimated time left, M0, how it ended).
#include "ProgramCheckStatus.h"
#include "ProgramControls.h"
#include "ProgramEditor.h"
#include "ProgramFiles.h"
#include "ProgramMachinePositions.h"
#include "ProgramPage.h"
#include "ProgramPreviewView.h"
#include "ProgramPromptBanner.h"
#include "ProgramStarter.h"
#include "common/Dialogs.h"
#include "common/ElidedLabel.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineMdi.h"
#include "program/MachineTools.h"
#include "program/MachineWorkOffsets.h"
#include "program/ProgramReader.h"
#include "program/RunFromLine.h"
#include <QPushButton>

namespace stepdeck::ui {

using program::RunState;

bool ProgramPage::isRunning() const
{
    if (!m_runner)
        return false;
    const RunState s = m_runner->state();
    return s == RunState::Running || s == RunState::Paused || s == RunState::Stopping;
}

void ProgramPage::abortRun()
{
    // A run whose check before it is still going never starts after STOP or PANIC.
    m_starter->cancel(tr("stopped while the program was checked before the run"));
    if (isRunning())
        m_runner->abort();
}

void ProgramPage::run()
{
    start(1, false);
}

void ProgramPage::step()
{
    if (m_runner && m_runner->state() == RunState::Paused)
        m_runner->step();
    else
        start(1, true);
}

QString ProgramPage::runFromText(int line) const
{
    QList<program::ProgramError> errors;
    const std::optional<program::Program> parsed = parse(&errors);
    std::optional<program::ProgramReader> reader;
    const program::ProgramBlock* first = nullptr;
    int index = -1;
    if (parsed) {
        reader.emplace(*parsed);
        index = reader->firstBlockAtLine(line);
        first = reader->at(index);
    }
    const machine::Machine* machine = m_context->machine();
    if (!first || !machine)
        return tr("Line %1: no block runs on or after it.").arg(line);
    const int firstLine = first->line;
    const QString firstText = first->text;
    // Issue 47 item 5: what the lines before it left switched on is switched on first, then the
    // axes go to where those lines leave the tool: what the run will send (RunFromState).
    const program::MachineFacts facts = machineFacts(*machine);
    const program::RunFromState from = program::RunFromState::before(*reader, index, facts);
    const QString restored = from.text();
    const QString approach = from.approachText(facts);
    QString text = tr("Run from line %1 (%2). The lines before it do not run; the axes start from "
                      "where they stand now: %3.")
                       .arg(firstLine)
                       .arg(firstText, ProgramMachinePositions::text(*machine));
    if (!restored.isEmpty())
        text += QLatin1Char(' ') + tr("First, as the lines before it left them: %1.").arg(restored);
    if (!approach.isEmpty())
        text += QLatin1Char(' ') +
                (restored.isEmpty()
                     ? tr("Moves first, to where the lines before it leave the tool: %1.")
                     : tr("Then moves to where the lines before it leave the tool: %1."))
                    .arg(approach);
    return text;
}

void ProgramPage::runFromLine(int line)
{
    if (!m_runner || isRunning())
        return;
    dialogs::message(this, QMessageBox::Question, tr("Run from line"), runFromText(line),
                     QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel,
                     [this, line](QMessageBox::StandardButton b) {
                         if (b == QMessageBox::Yes)
                             start(line, false);
                     });
}

bool ProgramPage::isStarting() const
{
    return m_starter->isPending();
}

// The check before the run goes off the GUI thread (ProgramStarter): a long program takes
// seconds, and STOP, PANIC and the window stay live meanwhile. Nothing moves until it passed.
bool ProgramPage::start(int fromLine, bool stepOnly)
{
    if (!m_runner || isRunning() || isStarting())
        return false;
    // Another runner holds the machine's motion (an MDI line, Go to): its words say which.
    const machine::Machine* open = m_context->machine();
    if (open && !open->motionHolder().isEmpty() && !open->holdsMotion(m_runner)) {
        onStartRefused({program::ProgramError{0, 0, open->motionHolder()}});
        return false;
    }
    m_recheck->stop();
    QList<program::ProgramError> errors;
    const std::optional<program::Program> parsed = parse(&errors);
    // In the coordinates the check used and the position display shows (issue 28, item 3).
    m_runner->setCoordinateSystems(m_context->workOffsets()->systems(),
                                   m_context->workOffsets()->active());
    m_runner->setToolTable(m_context->tools()->table());
    if (!parsed || !m_starter->request(m_runner, *parsed, fromLine, stepOnly)) {
        onStartRefused(errors);
        return false;
    }
    m_editor->setRunning(true); // the text that runs is the one checked now
    m_files->setEnabled(false);
    m_checkStatus->started();
    m_banner->setStatus(tr("Checking the program before the run…"));
    updateControls();
    return true;
}

void ProgramPage::onStarted(const program::Program& program)
{
    m_checkStatus->finished();
    m_running = program;
    m_progress.reset(m_runner->preview());
    m_stoppingText.clear();
    m_banner->clearPrompt();
    onState(m_runner->state());
}

void ProgramPage::onStartRefused(const QList<program::ProgramError>& errors)
{
    m_checkStatus->finished();
    m_editor->setRunning(false);
    m_files->setEnabled(true);
    m_editor->setErrors(errors);
    m_banner->setStatus(errors.isEmpty() ? tr("Not started.")
                                         : tr("Not started: %1").arg(errors.first().text()));
    updateControls();
    if (m_context->machine())
        m_recheck->start(); // the check line follows the machine again
}

void ProgramPage::onState(RunState state)
{
    const bool running = isRunning();
    Q_EMIT programRunning(running && state != RunState::Paused);
    if (state != RunState::Paused)
        m_holdNote.clear();
    m_editor->setRunning(running);
    m_files->setEnabled(!running);
    if (state == RunState::Running)
        m_banner->clearPrompt();
    if (!running) {
        m_banner->clearPrompt();
        m_preview->clearCurrent();
    }
    updateControls();
    updateProgress();
}

void ProgramPage::onBlockStarted(int line, const QString&)
{
    m_editor->setRunningLine(line);
    m_preview->setRunningLine(line);
    updateControls();
    updateProgress();
}

void ProgramPage::onBlockFinished(int line)
{
    m_progress.blockFinished(line);
    m_preview->setCurrent(workPositions(), m_progress.secondsDone());
    updateProgress();
}

void ProgramPage::onPaused(int line, const QString& prompt)
{
    if (m_runner->pausedAtOperatorStop()) {
        m_banner->showPrompt(line, prompt);
        m_banner->showKeepZ(m_runner->sameToolResumable()); // a touch-off M6 (issue 50)
    }
    updateControls();
}

void ProgramPage::onFinished(RunState state, const QString& message)
{
    QString text;
    // Issue 47, item 11: the count the preview names ("n block(s) run", ProgramPreview::
    // blocksRun: every block in run order, repeats counted out, lines of modal words only
    // included), of the check the run started with (from its first line). A run that finished
    // ran each of them; ProgramRunner::blocksDone() leaves out the modal-only lines it passes
    // by, so it would name fewer than the preview for the same run.
    if (state == RunState::Finished)
        text = tr("Finished: %n block(s) run.", nullptr,
                  int(qMin<qint64>(m_runner->preview().blocksRun, INT_MAX)));
    else if (state == RunState::Failed)
        text = tr("Failed: %1").arg(message);
    else
        text = message.isEmpty() ? tr("Aborted.") : tr("Aborted: %1").arg(message);
    onState(state);
    m_banner->setStatus(text);
    checkNow(); // the machine stands elsewhere now
}

void ProgramPage::updateControls()
{
    const RunState state = m_runner ? m_runner->state() : RunState::Idle;
    const machine::Machine* machine = m_context->machine();
    const machine::MachineState ms =
        machine ? machine->state() : machine::MachineState::Disconnected;
    const bool connected =
        ms != machine::MachineState::Disconnected && ms != machine::MachineState::LinkLost;
    const bool pausePending = m_runner && m_runner->pausePending();
    // Issue 33: a program in LinuxCNC's language runs its lines in its control flow's order.
    m_controls->setRunFromRefusal(
        m_checkOk && m_checkedProgram && m_checkedProgram->expansion
            ? tr("This program has parameters or O words: its lines run in the order its "
                 "control flow gives, so it runs from its start")
            : QString());
    m_controls->setState(state, pausePending,
                         m_checkOk && connected && !isStarting() && !m_context->mdi()->isBusy());
    if (!m_runner)
        return;
    const int line = m_runner->currentLine();
    if (state == RunState::Running)
        m_banner->setStatus(
            pausePending ? tr("Pausing: line %1 finishes first, then the program holds.").arg(line)
                         : tr("Running line %1.").arg(line));
    else if (state == RunState::Paused)
        m_banner->setStatus(
            !m_holdNote.isEmpty() ? m_holdNote
            // Issue 47 item 8: a feed hold stands in the middle of its line, not after it.
            : m_runner->feedHeld()
                ? tr("Feed hold in line %1: the tool stands on its path; Resume goes on from "
                     "there.")
                      .arg(line)
                : tr("Paused after line %1: Resume or Step goes on.").arg(line));
    else if (state == RunState::Stopping)
        m_banner->setStatus(m_stoppingText.isEmpty()
                                ? tr("Aborting: waiting for the axes to stand.")
                                : tr("Aborting: %1").arg(m_stoppingText));
    Q_EMIT jobChanged(isStarting() ? RunState::Idle : state, line);
}

void ProgramPage::updateProgress()
{
    if (!m_runner || m_runner->state() == RunState::Idle) {
        m_controls->clearProgress();
        return;
    }
    // Issue 47, item 11: the feed moves' rest at the run's override; ProgramControls shows it
    // again at once when the override changes.
    m_progress.setFeedOverride(m_runner->feedOverride());
    std::optional<ProgramTimeLeft> left = m_progress.timeLeft();
    if (program::isEnded(m_runner->state()))
        left = m_runner->state() == RunState::Finished
                   ? std::optional<ProgramTimeLeft>(ProgramTimeLeft{})
                   : std::nullopt;
    const int line =
        m_runner->currentLine() > 0 ? m_runner->currentLine() : m_editor->runningLine();
    m_controls->setProgress(line, m_running.lines, left);
}

} // namespace stepdeck::ui
