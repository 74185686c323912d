#pragma once
#include "ProgramTimes.h"
#include "program/ProgramRunner.h"
#include <QWidget>
#include <optional>

class QCheckBox;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace stepdeck::ui {

class ElidedLabel;

// Run, Pause, Resume, Step, Abort and "Run from line" of the Program page (issue 20), the
// optional-stop switch for M1 (issue 29), and the progress ("line n of m") with the estimated
// time left, in progressRow() for the page to place (issue 31: over the preview, where the
// operator watches the run; the buttons' two rows then fit beside it). Only buttons that do
// something in the state shown are enabled; the buttons never move (one-line texts). The
// controls only ask (signals): the page owns the runner.
class ProgramControls : public QWidget
{
    Q_OBJECT
public:
    explicit ProgramControls(QWidget* parent = nullptr);

    // The runner's state; canStart: a checked program and a connected machine are there.
    void setState(program::RunState state, bool pausePending, bool canStart);
    // Why the checked program cannot run from a line (its tooltip then); empty: it can.
    void setRunFromRefusal(const QString& why);
    // The line running of lines in the file; left: the estimate's rest (nullopt: unknown),
    // shown at the feed override set here, and again whenever it changes (issue 47, item 11).
    void setProgress(int line, int lines, std::optional<ProgramTimeLeft> left);
    void clearProgress();
    void setLineCount(int lines); // the range of "Run from line"

    QPushButton* runButton() const { return m_run; }
    QPushButton* pauseButton() const { return m_pause; }
    QPushButton* holdButton() const { return m_hold; }
    QPushButton* resumeButton() const { return m_resume; }
    QPushButton* stepButton() const { return m_step; }
    QPushButton* abortButton() const { return m_abort; }
    QPushButton* runFromButton() const { return m_runFrom; }
    QSpinBox* fromLineBox() const { return m_fromLine; }
    // LinuxCNC's optional-stop switch: on, M1 holds like M0. Remembered in QSettings
    // ("programs/optionalStops"); on when nothing was stored, as the runner's default.
    QCheckBox* optionalStopsBox() const { return m_optionalStops; }
    bool optionalStops() const;
    // LinuxCNC's block delete switch (issue 50 item 6): on, lines starting with "/" are skipped.
    // It is read by the check (MachineFacts::blockDelete), so the page checks again when it
    // changes; a run keeps what its check read. Remembered in QSettings ("programs/blockDelete");
    // on when nothing was stored, as LinuxCNC starts.
    QCheckBox* blockDeleteBox() const { return m_blockDelete; }
    bool blockDelete() const;
    QSpinBox* feedOverrideBox() const { return m_feedOverride; }
    int feedOverride() const; // percent
    QProgressBar* progressBar() const { return m_progress; }
    QWidget* progressRow() const { return m_progressRow; }
    QString progressText() const;
    QString timeLeftText() const;

Q_SIGNALS:
    void runRequested();
    void runFromLineRequested(int line);
    void pauseRequested();
    void holdRequested();
    void resumeRequested();
    void stepRequested();
    void abortRequested();
    void optionalStopsChanged(bool on);
    void blockDeleteChanged(bool on);
    void feedOverrideChanged(int percent);

private:
    QPushButton* m_run;
    QPushButton* m_pause;
    QPushButton* m_hold;
    QPushButton* m_resume;
    QPushButton* m_step;
    QPushButton* m_abort;
    QSpinBox* m_fromLine;
    QPushButton* m_runFrom;
    QString m_runFromRefusal;
    QCheckBox* m_optionalStops;
    QCheckBox* m_blockDelete;
    QSpinBox* m_feedOverride;
    void setUpFeedOverride();
    void showTimeLeft();
    QWidget* m_progressRow;
    QProgressBar* m_progress;
    ElidedLabel* m_timeLeft;
    bool m_showsProgress = false;
    std::optional<ProgramTimeLeft> m_left; // of the progress shown
};

} // namespace stepdeck::ui
