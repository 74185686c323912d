#include "ProgramControls.h"
#include "ProgramTimes.h"
#include "common/ElidedLabel.h"
#include <QCheckBox>
#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace stepdeck::ui {

using program::RunState;

namespace {
const QString kOptionalStopsKey = QStringLiteral("programs/optionalStops");
const QString kBlockDeleteKey = QStringLiteral("programs/blockDelete");
} // namespace

ProgramControls::ProgramControls(QWidget* parent)
    : QWidget(parent), m_run(new QPushButton(tr("Run"), this)),
      m_pause(new QPushButton(tr("&Pause"), this)), m_hold(new QPushButton(tr("Hold"), this)),
      m_resume(new QPushButton(tr("Resume"), this)), m_step(new QPushButton(tr("Step"), this)),
      m_abort(new QPushButton(tr("&Abort"), this)), m_fromLine(new QSpinBox(this)),
      m_runFrom(new QPushButton(tr("Run from line\u2026"), this)),
      m_optionalStops(new QCheckBox(tr("Optional stops (M1)"), this)),
      m_blockDelete(new QCheckBox(tr("Block delete (/)"), this)),
      m_feedOverride(new QSpinBox(this)), m_progressRow(new QWidget(this)),
      m_progress(new QProgressBar(m_progressRow)), m_timeLeft(new ElidedLabel(m_progressRow))
{
    setObjectName(QStringLiteral("programControls"));
    m_run->setObjectName(QStringLiteral("programRun"));
    m_pause->setObjectName(QStringLiteral("programPause"));
    m_hold->setObjectName(QStringLiteral("programHold"));
    m_resume->setObjectName(QStringLiteral("programResume"));
    m_step->setObjectName(QStringLiteral("programStep"));
    m_abort->setObjectName(QStringLiteral("programAbort"));
    m_runFrom->setObjectName(QStringLiteral("programRunFrom"));
    m_fromLine->setObjectName(QStringLiteral("programFromLine"));
    m_optionalStops->setObjectName(QStringLiteral("programOptionalStops"));
    setUpFeedOverride();
    m_progress->setObjectName(QStringLiteral("programProgress"));
    m_timeLeft->setObjectName(QStringLiteral("programTimeLeft"));
    // No mnemonics on what starts motion: a stray Alt+key must not start a program.
    m_run->setToolTip(tr("Check the program against the machine and run it from the start"));
    m_pause->setToolTip(tr("Finish the current block, then hold"));
    m_hold->setToolTip(tr("Feed hold: stop on the path where the tool is (a contour); a block "
                          "of its own finishes first. Resume goes on from there. Key: F2"));
    m_resume->setToolTip(tr("Go on with the next block"));
    m_step->setToolTip(tr("Run one block, then hold"));
    m_abort->setToolTip(tr("Stop every controller; the program ends as aborted"));
    m_runFrom->setToolTip(tr("Run from the first block on or after this line, starting where "
                             "the axes stand now"));
    m_optionalStops->setToolTip(
        tr("On: the program holds at M1 like at M0 (LinuxCNC's optional stop). Off: it runs "
           "past every M1. Counts when the run reaches the M1."));
    // On unless the operator switched it off: a forgotten stop is safer than a missed one.
    m_optionalStops->setChecked(QSettings().value(kOptionalStopsKey, true).toBool());
    m_blockDelete->setObjectName(QStringLiteral("programBlockDelete"));
    m_blockDelete->setToolTip(
        tr("On: lines starting with \"/\" are skipped (LinuxCNC's block delete, on as LinuxCNC "
           "starts). Off: they run without the \"/\". The program is checked again when it "
           "changes; a run keeps what its check read."));
    m_blockDelete->setChecked(QSettings().value(kBlockDeleteKey, true).toBool());
    m_fromLine->setRange(1, 1);
    m_fromLine->setPrefix(tr("line "));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    // Narrow minimums: the row shares the page with the run's buttons at 1366x768; wider, the
    // time left gets its whole text.
    m_progress->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("0")) * 14);
    m_timeLeft->setMinimumTextWidth(fontMetrics().horizontalAdvance(QStringLiteral("0")) * 22);

    // Two rows, so that the page fits the Run workspace's width at 1366x768 (issue 31): the
    // run's buttons and the feed override, then where to start and M1. The progress in a row
    // of its own.
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setSpacing(2);
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {m_run, m_pause, m_hold, m_resume, m_step, m_abort})
        buttons->addWidget(b);
    buttons->addSpacing(8);
    buttons->addWidget(m_feedOverride);
    buttons->addStretch(1);
    auto* where = new QHBoxLayout;
    where->addWidget(m_fromLine);
    where->addWidget(m_runFrom);
    where->addSpacing(8);
    where->addWidget(m_optionalStops);
    where->addWidget(m_blockDelete);
    where->addStretch(1);
    auto* progress = new QHBoxLayout(m_progressRow);
    progress->setContentsMargins(0, 0, 0, 0);
    progress->addWidget(m_progress, 1);
    progress->addWidget(m_timeLeft);
    rows->addLayout(buttons);
    rows->addLayout(where);

    connect(m_run, &QPushButton::clicked, this, &ProgramControls::runRequested);
    connect(m_pause, &QPushButton::clicked, this, &ProgramControls::pauseRequested);
    connect(m_hold, &QPushButton::clicked, this, &ProgramControls::holdRequested);
    connect(m_resume, &QPushButton::clicked, this, &ProgramControls::resumeRequested);
    connect(m_step, &QPushButton::clicked, this, &ProgramControls::stepRequested);
    connect(m_abort, &QPushButton::clicked, this, &ProgramControls::abortRequested);
    connect(m_runFrom, &QPushButton::clicked, this,
            [this] { Q_EMIT runFromLineRequested(m_fromLine->value()); });
    connect(m_optionalStops, &QCheckBox::toggled, this, [this](bool on) {
        QSettings().setValue(kOptionalStopsKey, on);
        Q_EMIT optionalStopsChanged(on);
    });
    connect(m_blockDelete, &QCheckBox::toggled, this, [this](bool on) {
        QSettings().setValue(kBlockDeleteKey, on);
        Q_EMIT blockDeleteChanged(on);
    });
    clearProgress();
    setState(RunState::Idle, false, false);
}

// Issue 30: 10..200 % in steps of 10, "F 100 %" (ProgramRunner::setFeedOverride).
void ProgramControls::setUpFeedOverride()
{
    m_feedOverride->setObjectName(QStringLiteral("programFeedOverride"));
    m_feedOverride->setRange(10, 200);
    m_feedOverride->setSingleStep(10);
    m_feedOverride->setValue(100);
    m_feedOverride->setPrefix(tr("F "));
    m_feedOverride->setSuffix(tr(" %"));
    m_feedOverride->setToolTip(
        tr("Feed override: a contour runs at this share of F, from its next ticks on (each move "
           "at most as fast as one step per tick allows); a block of its own runs at its F"));
    connect(m_feedOverride, qOverload<int>(&QSpinBox::valueChanged), this,
            &ProgramControls::feedOverrideChanged);
    // The time left follows the override at once, not at the next block's end.
    connect(m_feedOverride, qOverload<int>(&QSpinBox::valueChanged), this,
            &ProgramControls::showTimeLeft);
}

void ProgramControls::setRunFromRefusal(const QString& why)
{
    m_runFromRefusal = why;
    m_runFrom->setToolTip(why.isEmpty() ? tr("Run from the first block on or after this line, "
                                             "starting where the axes stand now")
                                        : why);
}

int ProgramControls::feedOverride() const
{
    return m_feedOverride->value();
}

bool ProgramControls::optionalStops() const
{
    return m_optionalStops->isChecked();
}

bool ProgramControls::blockDelete() const
{
    return m_blockDelete->isChecked();
}

void ProgramControls::setState(RunState state, bool pausePending, bool canStart)
{
    const bool ended = state == RunState::Idle || program::isEnded(state);
    m_run->setEnabled(ended && canStart);
    m_runFrom->setEnabled(ended && canStart && m_runFromRefusal.isEmpty());
    m_fromLine->setEnabled(ended);
    m_blockDelete->setEnabled(ended); // read by the check: a run keeps what its check read
    m_pause->setEnabled(state == RunState::Running && !pausePending);
    m_hold->setEnabled(state == RunState::Running);
    m_resume->setEnabled(state == RunState::Paused);
    // Step from a pause, or the first block of a program that does not run yet.
    m_step->setEnabled(state == RunState::Paused || (ended && canStart));
    m_abort->setEnabled(state == RunState::Running || state == RunState::Paused);
}

void ProgramControls::setProgress(int line, int lines, std::optional<ProgramTimeLeft> left)
{
    m_progress->setRange(0, qMax(1, lines));
    m_progress->setValue(qBound(0, line, qMax(1, lines)));
    m_progress->setFormat(tr("line %1 of %2").arg(line).arg(lines));
    m_showsProgress = true;
    m_left = left;
    showTimeLeft();
}

// The feed moves' part at the override the spin box shows, which is the runner's
// (ProgramPage passes every change on to ProgramRunner::setFeedOverride).
void ProgramControls::showTimeLeft()
{
    if (!m_showsProgress)
        return;
    m_timeLeft->setText(m_left ? ProgramTimes::estimatedLeft(m_left->at(feedOverride()))
                               : tr("time left unknown"));
}

void ProgramControls::clearProgress()
{
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(tr("not running"));
    m_showsProgress = false;
    m_left.reset();
    m_timeLeft->setText(QString());
}

void ProgramControls::setLineCount(int lines)
{
    m_fromLine->setRange(1, qMax(1, lines));
}

QString ProgramControls::progressText() const
{
    return m_progress->text();
}

QString ProgramControls::timeLeftText() const
{
    return m_timeLeft->text();
}

} // namespace stepdeck::ui
