#pragma once
#include "ProgramProgress.h"
#include "program/ProgramCheck.h"
#include "program/ProgramRunner.h"
#include <QPointer>
#include <QWidget>
#include <optional>

class QProgressBar;
class QPushButton;
class QTimer;

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;
class MdiLine;
class ProgramBackgroundCheck;
class ProgramStarter;
class ProgramCheckStatus;
class ProgramControls;
class ProgramEditor;
class ProgramErrorList;
class ProgramFiles;
class ProgramPreviewView;
class ProgramPromptBanner;

// The Program page (issue 20, docs/programs.md): a motion program's file and text, checked
// against the open machine while it is edited (debounced: ProgramParser, then ProgramCheck
// with factsOf(machine)), the errors marked at their lines and listed in the preview's Errors tab
// (ProgramErrorList), the preview beside it, and the run through a ProgramRunner on the
// context's machine: Run, Pause, Resume, Step, Abort, Run from line N (after a confirmation
// naming where the axes stand), the running line highlighted, "line n of m" with the estimated
// time left, M0's prompt in a banner with Resume. The text is read-only while a program runs.
// STOP and PANIC of the window end a running program as aborted (MainWindow calls abortRun()
// before it stops the machine). Programs run on the machine (every connection is one, issue 28
// item 0). "(MSG, text)" lines reach the window as operatorMessage().
class ProgramPage : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramPage(MachineContext* context, QWidget* parent = nullptr);
    ~ProgramPage() override;

    ProgramEditor* editor() const { return m_editor; }
    ProgramErrorList* errorList() const { return m_errorList; }
    ProgramPreviewView* preview() const { return m_preview; }
    ProgramControls* controls() const { return m_controls; }
    ProgramPromptBanner* promptBanner() const { return m_banner; }
    ProgramFiles* files() const { return m_files; }
    MdiLine* mdiLine() const { return m_mdiLine; }
    program::ProgramRunner* runner() const { return m_runner; }
    QString checkText() const;
    QString checkToolTip() const; // every note of the check, a line each
    QString messageText() const;
    bool isRunning() const;
    // Run was pressed and the check before it runs (ProgramStarter): nothing moves yet.
    bool isStarting() const;
    // The check of the text as it stands now, without waiting for the debounce; it runs off
    // the GUI thread (ProgramBackgroundCheck) and reports when done (isChecking() until then).
    // A file too long to edit (ProgramFiles::largePath()) is checked from the file.
    void checkNow();
    QProgressBar* checkProgress() const;
    bool isShowingCheckProgress() const;
    // How long a check runs before its progress shows (0.3 s; tests take 0).
    void setCheckProgressDelay(int ms);
    QPushButton* cancelCheckButton() const;
    bool isChecking() const;
    // What the confirmation of "Run from line" says about where the run starts.
    QString runFromText(int line) const;

Q_SIGNALS:
    // The run reached a line with "(MSG, text)" (LinuxCNC): the window shows it.
    void operatorMessage(int line, const QString& text);
    // A program runs (not held at M0/M6 or paused): it owns spindle and coolant meanwhile.
    void programRunning(bool running);
    // The run's state and its line, for the safety banner (issue 47 item 15).
    void jobChanged(stepdeck::program::RunState state, int line);

public Q_SLOTS:
    // The window's STOP or PANIC: a running program ends as aborted.
    void abortRun();
    void run();
    void runFromLine(int line);
    void step();

private:
    void buildLayout();
    void onMachineChanged();
    void connectFeedControls();
    void onMachineStatus();
    bool rulesFactsChanged() const; // since the last check (m_checkedParameters, ...)
    // The open machine's facts in the position display's coordinates and with the machine's
    // tool table: what the check judges and a run takes (ProgramRunner::startFacts).
    program::MachineFacts machineFacts(const machine::Machine& machine) const;
    std::optional<program::Program> parse(QList<program::ProgramError>* errors) const;
    bool start(int fromLine, bool stepOnly);
    void onStarted(const program::Program& program);
    void onStartRefused(const QList<program::ProgramError>& errors);
    void showCheck(const program::ProgramCheckResult& result);
    void showErrors(const QList<program::ProgramError>& errors); // marked, listed
    // A clean check's notes on the check line: the count and the first, every one in its tip.
    void showNotes(const QList<program::ProgramError>& notes);
    void cancelCheck();
    void updateControls();
    void updateProgress();
    // The runner's signals.
    void onState(program::RunState state);
    void onBlockStarted(int line, const QString& text);
    void onBlockFinished(int line);
    void onPaused(int line, const QString& prompt);
    void onFinished(program::RunState state, const QString& message);
    // The known positions in the running program's work coordinates (the preview's).
    QMap<QString, double> workPositions() const;
    QString positionsSignature() const;

    MachineContext* m_context;
    ProgramFiles* m_files;
    ElidedLabel* m_machineNote;
    ElidedLabel* m_check;
    ProgramCheckStatus* m_checkStatus = nullptr; // m_check, or a long check's progress
    ProgramEditor* m_editor;
    ProgramErrorList* m_errorList;
    ProgramPreviewView* m_preview;
    ProgramPromptBanner* m_banner;
    // While the run holds: why Resume did not go on, or that it checks new offsets first.
    QString m_holdNote;
    ProgramControls* m_controls;
    MdiLine* m_mdiLine;
    QTimer* m_recheck;
    ProgramBackgroundCheck* m_checker;
    ProgramStarter* m_starter;
    program::ProgramRunner* m_runner = nullptr;
    QPointer<machine::Machine> m_runnerMachine;
    bool m_checkOk = false;
    std::optional<program::Program> m_checkedProgram; // of the last check without errors
    program::Program m_running; // what the runner runs (for M0 lines and the progress)
    ProgramProgress m_progress; // of the run, in the estimate
    QString m_checkedPositions; // positionsSignature() of the last check
    // What the rules of the last check judged by (issue 28: a setup written on the Setup page
    // checks the program again): per controller its known parameters and incomplete setup.
    QMap<QString, ParameterSet> m_checkedParameters;
    QSet<QString> m_checkedIncomplete;
    QString m_stoppingText; // the runner's stopping(): a move runs out by itself
};

} // namespace stepdeck::ui
