// ProgramPage, part 1: the layout, the machine the page works on, and the check while editing.
// The run itself is in ProgramPageRun.cpp.
#include "ProgramPage.h"
#include "MdiLine.h"
#include "ProgramBackgroundCheck.h"
#include "ProgramCheckStatus.h"
#include "ProgramControls.h"
#include "ProgramEditor.h"
#include "ProgramErrorList.h"
#include "ProgramFiles.h"
#include "ProgramMachinePositions.h"
#include "ProgramPathView.h"
#include "ProgramPreviewView.h"
#include "ProgramPromptBanner.h"
#include "ProgramStarter.h"
#include "common/ElidedLabel.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include "machine/MachineMdi.h"
#include "program/MachineTools.h"
#include "program/MachineWorkOffsets.h"
#include "program/ProgramParser.h"
#include "program/language/ProgramExpansion.h"
#include <QHBoxLayout>
#include <QPushButton>
#include <QShortcut>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

namespace stepdeck::ui {

namespace {
constexpr int kRecheckDelayMs = 400;
} // namespace

ProgramPage::ProgramPage(MachineContext* context, QWidget* parent)
    : QWidget(parent), m_context(context), m_machineNote(new ElidedLabel(this, 2)),
      m_check(new ElidedLabel(this)), m_editor(new ProgramEditor(this)),
      m_errorList(new ProgramErrorList(m_editor, this)), m_preview(new ProgramPreviewView(this)),
      m_banner(new ProgramPromptBanner(this)), m_controls(new ProgramControls(this)),
      m_mdiLine(new MdiLine(context, this)), m_recheck(new QTimer(this)),
      m_checker(new ProgramBackgroundCheck(this)), m_starter(new ProgramStarter(this))
{
    setObjectName(QStringLiteral("programPage"));
    m_files = new ProgramFiles(m_editor, this);
    m_machineNote->setObjectName(QStringLiteral("programMachineNote"));
    m_check->setObjectName(QStringLiteral("programCheck"));
    m_recheck->setSingleShot(true);
    m_recheck->setInterval(kRecheckDelayMs);
    buildLayout();

    connect(m_recheck, &QTimer::timeout, this, &ProgramPage::checkNow);
    // One run at a time on the machine, the MDI line's or the program's: the machine's motion
    // has one holder (Machine::claimMotion), and its STOP, PANIC or close end the holder's.
    m_starter->setStopReason(tr("stopped while the program was checked before the run"));
    connect(context->mdi(), &MachineMdi::busyChanged, this, &ProgramPage::updateControls);
    connect(m_checker, &ProgramBackgroundCheck::checked, this, &ProgramPage::showCheck);
    connect(m_checker, &ProgramBackgroundCheck::progress, m_checkStatus,
            &ProgramCheckStatus::setProgress);
    connect(m_checkStatus, &ProgramCheckStatus::cancelRequested, this, &ProgramPage::cancelCheck);
    connect(m_starter, &ProgramStarter::progress, m_checkStatus, &ProgramCheckStatus::setProgress);
    connect(m_starter, &ProgramStarter::started, this, &ProgramPage::onStarted);
    connect(m_starter, &ProgramStarter::refused, this, &ProgramPage::onStartRefused);
    connect(m_checkStatus, &ProgramCheckStatus::checkRequested, this, &ProgramPage::checkNow);
    connect(m_editor, &QPlainTextEdit::textChanged, this, [this] {
        if (!isRunning())
            m_recheck->start(); // again from now: typing does not check every key
    });
    connect(m_files, &ProgramFiles::message, this,
            [this](const QString& text) { m_banner->setStatus(text); });
    connect(m_files, &ProgramFiles::loaded, this, [this] {
        // Another program: what was said of the last one (its run's end, "too large to edit")
        // goes, and its preview is fitted to the view, whatever the last one's zoom.
        m_banner->setStatus(QString());
        m_controls->clearProgress();
        m_preview->pathView()->fitToView();
        checkNow();
    });
    connect(m_banner, &ProgramPromptBanner::resumeRequested, this, [this] {
        if (m_runner)
            m_runner->resume();
    });
    // Issue 50 item 4: on from a touch-off M6 without a new Z, where the runner offers it.
    connect(m_banner, &ProgramPromptBanner::keepZRequested, this, [this] {
        if (m_runner)
            m_runner->resumeSameTool();
    });
    connect(m_controls, &ProgramControls::runRequested, this, &ProgramPage::run);
    connect(m_controls, &ProgramControls::runFromLineRequested, this, &ProgramPage::runFromLine);
    connect(m_controls, &ProgramControls::stepRequested, this, &ProgramPage::step);
    connect(m_controls, &ProgramControls::pauseRequested, this, [this] {
        if (m_runner)
            m_runner->pause();
        updateControls();
    });
    connectFeedControls();
    connect(m_controls, &ProgramControls::resumeRequested, this, [this] {
        if (m_runner)
            m_runner->resume();
    });
    connect(m_controls, &ProgramControls::abortRequested, this, &ProgramPage::abortRun);
    connect(m_controls, &ProgramControls::optionalStopsChanged, this, [this](bool on) {
        if (m_runner)
            m_runner->setOptionalStops(on); // also while a program runs: counts at its next M1
    });
    // Block delete decides which lines the check reads (issue 50 item 6): checked again. The
    // switch is off while a program runs (ProgramControls), whose check read it already.
    connect(m_controls, &ProgramControls::blockDeleteChanged, this, [this] {
        if (!isRunning())
            m_recheck->start();
    });
    connect(m_context, &MachineContext::machineChanged, this, &ProgramPage::onMachineChanged);
    connect(m_context, &MachineContext::machineStatusChanged, this, &ProgramPage::onMachineStatus);
    // A new work zero or tool table moves the program's path on the machine: checked again.
    // While a run holds they are the rest's too, checked at Resume (ProgramRunner, issue 47).
    const auto recheck = [this] {
        if (!isRunning()) {
            m_recheck->start();
        } else if (m_runner->state() == program::RunState::Paused) {
            m_runner->setToolTable(m_context->tools()->table());
            m_runner->setCoordinateSystems(m_context->workOffsets()->systems(),
                                           m_context->workOffsets()->active());
            m_holdNote = m_runner->restNeedsCheck()
                             ? tr("The offsets or tools changed while the run holds: Resume "
                                  "checks the rest of the program with them first.")
                             : QString();
            m_banner->showKeepZ(m_runner->sameToolResumable()); // a Zero Z ends the offer
            updateControls();
        }
    };
    connect(m_context->workOffsets(), &program::MachineWorkOffsets::changed, this, recheck);
    connect(m_context->tools(), &program::MachineTools::changed, this, recheck);
    // The single controller's link decides whether "Use the connected controller" can work.
    connect(m_context->session(), &ControllerSession::linkStateChanged, this,
            &ProgramPage::updateControls);
    onMachineChanged();
}

ProgramPage::~ProgramPage() = default;

namespace {
// A column that asks for no more than it needs: the splitter gives the rest to the preview.
class CompactColumn : public QWidget
{
public:
    using QWidget::QWidget;
    QSize sizeHint() const override { return minimumSizeHint(); }
};
} // namespace

void ProgramPage::buildLayout()
{
    // Left, the rows of the run over the program's text: the files, the run's buttons and
    // progress, the MDI line, the run's message (M0's prompt), the program's figures. Right,
    // the check and the machine over the preview: the toolpath is what the operator watches,
    // and the Run workspace's program dock is wide and low (issue 31).
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->setObjectName(QStringLiteral("programSplitter"));
    auto* run = new CompactColumn(split);
    auto* v = new QVBoxLayout(run);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(3);
    v->addWidget(m_files);
    v->addWidget(m_controls);
    v->addWidget(m_mdiLine);
    v->addWidget(m_banner);
    v->addWidget(m_preview->summary());
    v->addWidget(m_editor, 1);
    auto* watch = new QWidget(split);
    auto* w = new QVBoxLayout(watch);
    w->setContentsMargins(0, 0, 0, 0);
    w->setSpacing(3);
    m_checkStatus = new ProgramCheckStatus(m_check, ProgramBackgroundCheck::kProgressSteps, this);
    w->addWidget(m_checkStatus);
    w->addWidget(m_controls->progressRow());
    w->addWidget(m_machineNote);
    // The preview holds its place whatever the check finds (issue 47 item 12): a program with
    // errors keeps the path its check walked, and the list of the errors is the preview's last
    // tab; a program that does not parse has no path, and the list is then the one tab shown.
    m_preview->setErrorList(m_errorList);
    w->addWidget(m_preview, 1);
    split->addWidget(run);
    split->addWidget(watch);
    // Width beyond the columns' least: a third to the text and the MDI line, the rest to the
    // preview.
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);
    split->setChildrenCollapsible(false);
    m_editor->setMinimumSize(200, 60);
    auto* page = new QVBoxLayout(this);
    page->setContentsMargins(4, 4, 4, 4);
    page->addWidget(split);
}

bool ProgramPage::isShowingCheckProgress() const
{
    return m_checkStatus->isShowingProgress();
}

void ProgramPage::setCheckProgressDelay(int ms)
{
    m_checkStatus->setDelay(ms);
}

QProgressBar* ProgramPage::checkProgress() const
{
    return m_checkStatus->progressBar();
}

QPushButton* ProgramPage::cancelCheckButton() const
{
    return m_checkStatus->cancelButton();
}

void ProgramPage::cancelCheck()
{
    if (m_starter->isPending()) { // the check before a run: the run does not start
        m_starter->cancel();
        return;
    }
    m_checker->cancel();
    m_checkStatus->finished();
    m_checkOk = false;
    m_checkedProgram.reset();
    m_check->setText(tr("Not checked: the check was cancelled. Run stays off until it is "
                        "checked."));
    m_check->setStyleSheet(QString());
    m_check->setToolTip(QString());
    m_preview->clear(tr("No preview: the check was cancelled."));
    updateControls();
}

QString ProgramPage::checkText() const
{
    return m_check->text();
}

QString ProgramPage::checkToolTip() const
{
    return m_check->toolTip();
}

QString ProgramPage::messageText() const
{
    return m_banner->statusText();
}

// Issue 30: feed hold from the Hold button and from anywhere in the window (F2, as STOP has
// Esc and PANIC F1); the feed override, also while a program runs.
void ProgramPage::connectFeedControls()
{
    const auto hold = [this] {
        if (m_runner && m_runner->state() == program::RunState::Running)
            m_runner->holdFeed();
        updateControls();
    };
    connect(m_controls, &ProgramControls::holdRequested, this, hold);
    auto* holdKey = new QShortcut(QKeySequence(Qt::Key_F2), this);
    holdKey->setContext(Qt::ApplicationShortcut);
    connect(holdKey, &QShortcut::activated, this, hold);
    connect(m_controls, &ProgramControls::feedOverrideChanged, this, [this](int percent) {
        if (m_runner)
            m_runner->setFeedOverride(percent);
        m_context->mdi()->setFeedOverride(percent); // MDI lines run at it too
    });
}

void ProgramPage::onMachineChanged()
{
    machine::Machine* machine = m_context->machine();
    // (A closed machine is gone before machineChanged: the pointer then reads null.)
    if (m_runner && (m_runnerMachine.isNull() || m_runnerMachine != machine)) {
        // The machine the runner ran on is closed (its controllers stopped with it).
        const bool wasRunning = isRunning();
        m_starter->cancel(); // a run about to start does not
        delete m_runner;
        m_runner = nullptr;
        m_editor->setRunning(false);
        m_files->setEnabled(true);
        m_banner->clearPrompt();
        m_preview->clearCurrent();
        m_controls->clearProgress();
        if (wasRunning) // else it ended already and says how
            m_banner->setStatus(tr("Aborted: the machine was closed."));
    }
    if (machine && !m_runner) {
        m_runner = new program::ProgramRunner(machine, this);
        m_runner->setOptionalStops(m_controls->optionalStops());
        m_runner->setFeedOverride(m_controls->feedOverride());
        m_runnerMachine = machine;
        using program::ProgramRunner;
        connect(m_runner, &ProgramRunner::stateChanged, this, &ProgramPage::onState);
        connect(m_runner, &ProgramRunner::blockStarted, this, &ProgramPage::onBlockStarted);
        connect(m_runner, &ProgramRunner::blockFinished, this, &ProgramPage::onBlockFinished);
        connect(m_runner, &ProgramRunner::paused, this, &ProgramPage::onPaused);
        connect(m_runner, &ProgramRunner::stopping, this, [this](const QString& message) {
            m_stoppingText = message; // said until the axes stand (updateControls)
            updateControls();
        });
        connect(m_runner, &ProgramRunner::finished, this, &ProgramPage::onFinished);
        connect(m_runner, &ProgramRunner::operatorMessage, this, &ProgramPage::operatorMessage);
        // A program's G10 sets a coordinate system for the next runs too (LinuxCNC).
        connect(m_runner, &ProgramRunner::coordinateSystemSet, m_context->workOffsets(),
                &program::MachineWorkOffsets::setSystem);
        // A touch-off while the run holds (issue 47): the rest of the run takes the new zero
        // or tool length once its check passed (ProgramRunner::resume); the banner says which.
        connect(m_runner, &ProgramRunner::resumeRefused, this, [this](const QString& message) {
            m_holdNote = message; // said while the run stays held
            // and in the window's log: at M0 or M6 the banner shows the prompt over it.
            Q_EMIT operatorMessage(m_runner->currentLine(), message);
            updateControls();
        });
        connect(m_runner, &ProgramRunner::restChecked, this, [this](const QString& message) {
            Q_EMIT operatorMessage(m_runner->currentLine(), message); // the window's log
        });
    }
    if (machine) {
        QStringList axes;
        for (const machine::MachineAxis& a : machine->description().axes)
            axes << a.name;
        m_machineNote->setText(
            tr("Runs on %1 (axes %2)")
                .arg(machine->description().name, axes.join(QStringLiteral(", "))));
    } else {
        m_machineNote->setText(tr("Programs run on a machine: choose a model on the connection "
                                  "bar or open a machine file."));
    }
    m_machineNote->setToolTip(m_machineNote->text());
    checkNow();
}

std::optional<program::Program> ProgramPage::parse(QList<program::ProgramError>* errors) const
{
    QStringList axes;
    if (const machine::Machine* machine = m_context->machine()) {
        for (const machine::MachineAxis& a : machine->description().axes)
            axes << a.name;
    }
    if (!m_files->largePath().isEmpty()) {
        // A file too long to edit: the program of its last check (the run checks it again,
        // and its reader refuses the file if it changed since).
        if (m_checkOk && m_checkedProgram)
            return m_checkedProgram;
        if (errors)
            *errors = {program::ProgramError{0, 0, tr("the program is not checked yet")}};
        return std::nullopt;
    }
    const QByteArray text = m_editor->toPlainText().toUtf8();
    if (program::ProgramExpansion::usesLanguage(text)) {
        // Parameters and O words are worked out against the machine's offsets by the check
        // (issue 33): the program its check read is the one that runs.
        if (m_checkOk && m_checkedProgram)
            return m_checkedProgram;
        if (errors)
            *errors = {program::ProgramError{0, 0, tr("the program is not checked yet")}};
        return std::nullopt;
    }
    return program::ProgramParser::parse(text, axes, errors, {}, m_controls->blockDelete());
}

void ProgramPage::checkNow()
{
    m_recheck->stop();
    if (isRunning() || isStarting())
        return; // the runner checked what runs; the text cannot change meanwhile
    if (m_files->largePath().isEmpty())
        m_controls->setLineCount(m_editor->blockCount());
    const machine::Machine* machine = m_context->machine();
    if (!machine) {
        m_checker->cancel();
        m_checkStatus->finished();
        m_checkOk = false;
        showErrors({});
        m_check->setText(tr("Not checked: no machine open."));
        m_preview->clear(tr("The preview needs a machine: its axes and soft limits."));
        updateControls();
        return;
    }
    QStringList axes;
    for (const machine::MachineAxis& a : machine->description().axes)
        axes << a.name;
    // Run stays off until the text as it is now has been checked.
    m_checkOk = false;
    updateControls();
    m_checkedPositions = positionsSignature();
    const program::MachineFacts facts = machineFacts(*machine);
    m_checkedParameters = facts.knownParameters;
    m_checkedIncomplete = facts.setupIncomplete;
    const QString large = m_files->largePath();
    m_checkStatus->started();
    m_checker->start(large.isEmpty()
                         ? program::ProgramSource::bytes(m_editor->toPlainText().toUtf8())
                         : program::ProgramSource::file(large),
                     axes, facts);
}

program::MachineFacts ProgramPage::machineFacts(const machine::Machine& machine) const
{
    program::MachineFacts facts = program::factsOf(machine);
    // The position display's coordinates: the active system, and the others for G54..G59.
    facts.coordinateSystems = m_context->workOffsets()->systems();
    facts.activeSystem = m_context->workOffsets()->active();
    facts.tools = m_context->tools()->table();
    facts.blockDelete = m_controls->blockDelete();
    return facts;
}

bool ProgramPage::isChecking() const
{
    return m_checker->isChecking() || m_recheck->isActive();
}

void ProgramPage::showCheck(const program::ProgramCheckResult& result)
{
    if (isRunning() || !m_context->machine())
        return; // a check of before the run or of a machine closed since
    m_checkStatus->finished();
    const bool large = !m_files->largePath().isEmpty();
    m_checkOk = result.ok() && (large ? result.program && result.program->blockCount > 0
                                      : !m_editor->toPlainText().trimmed().isEmpty());
    m_checkedProgram = result.ok() ? result.program : std::nullopt;
    if (large)
        m_controls->setLineCount(result.preview.lines);
    if (result.ok()) {
        m_check->setText(m_checkOk ? tr("Checked against the machine: no errors.")
                                   : tr("No program."));
        m_check->setStyleSheet(QString());
        m_check->setToolTip(QString());
        if (m_checkOk && !result.notes.isEmpty())
            showNotes(result.notes); // issue 50: e.g. a feed above the machine's highest
        if (m_checkOk)
            m_preview->setPreview(result.preview, m_context->machine()->description());
        else
            m_preview->clear(tr("No program."));
    } else {
        const program::ProgramError& first = result.errors.first();
        m_check->setText(tr("%n error(s); line %1: %2", nullptr, int(result.errors.size()))
                             .arg(first.line)
                             .arg(first.message));
        m_check->setStyleSheet(QStringLiteral("QLabel { color: #b00000; }"));
        QStringList all;
        for (const program::ProgramError& e : result.errors)
            all << e.text();
        m_check->setToolTip(all.join(QLatin1Char('\n')));
        // Issue 47 item 12: errors that leave a path (soft limits, rates, unknown positions)
        // keep it in view, marked as not runnable, so that the operator sees where the program
        // goes (the part, to place a work zero); Run stays off (m_checkOk). A program that does
        // not parse has none: the list alone.
        if (result.hasPreview())
            m_preview->setPreview(result.preview, m_context->machine()->description());
        else
            m_preview->clear(tr("No preview: the program has errors."));
    }
    showErrors(result.errors); // after the preview: the errors' tab follows whether it has one
    updateControls();
}

// What runs otherwise than written without being refused (issue 50: a feed above the machine's
// highest runs at it, as LinuxCNC and GRBL do) is said, not hidden: the operator sees it before
// Run, but nothing turns red and Run stays on.
void ProgramPage::showNotes(const QList<program::ProgramError>& notes)
{
    const program::ProgramError& first = notes.first();
    m_check->setText(tr("Checked against the machine: no errors; %n note(s), line %1: %2", nullptr,
                        int(notes.size()))
                         .arg(first.line)
                         .arg(first.message));
    QStringList all;
    for (const program::ProgramError& n : notes)
        all << n.text();
    m_check->setToolTip(all.join(QLatin1Char('\n')));
}

void ProgramPage::showErrors(const QList<program::ProgramError>& errors)
{
    m_editor->setErrors(errors);
    m_errorList->setErrors(errors);
    m_preview->setErrorCount(int(errors.size()));
}

void ProgramPage::onMachineStatus()
{
    // Where the axes stand is part of the check (known positions, relative moves): once the
    // machine rests somewhere new, or an axis became known, the text is checked again.
    if (!isRunning() && !isStarting() && !m_recheck->isActive() &&
        (positionsSignature() != m_checkedPositions || rulesFactsChanged()))
        m_recheck->start();
    if (isRunning())
        m_preview->setCurrent(workPositions(), m_progress.secondsDone());
    updateControls();
}

QMap<QString, double> ProgramPage::workPositions() const
{
    const machine::Machine* machine = m_context->machine();
    if (!machine)
        return {};
    QMap<QString, double> positions = ProgramMachinePositions::known(*machine);
    const QMap<QString, double> offsets =
        m_runner ? m_runner->workOffsets() : m_context->workOffsets()->all();
    for (auto it = positions.begin(); it != positions.end(); ++it)
        it.value() -= offsets.value(it.key(), 0.0);
    return positions;
}

bool ProgramPage::rulesFactsChanged() const
{
    const machine::Machine* machine = m_context->machine();
    if (!machine)
        return false;
    const program::MachineFacts facts = program::factsOf(*machine);
    return facts.knownParameters != m_checkedParameters ||
           facts.setupIncomplete != m_checkedIncomplete;
}

QString ProgramPage::positionsSignature() const
{
    const machine::Machine* machine = m_context->machine();
    if (!machine)
        return {};
    // Not while anything moves: once it rests.
    return ProgramMachinePositions::restingSignature(*machine).value_or(m_checkedPositions);
}

} // namespace stepdeck::ui
