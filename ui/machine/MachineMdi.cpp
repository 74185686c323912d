#include "MachineMdi.h"
#include "MachineContext.h"
#include "machine/Machine.h"
#include "program/MachineTools.h"
#include "program/MachineWorkOffsets.h"
#include "program/ProgramStarter.h"
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcMdi, "stepdeck.ui.mdi")

namespace stepdeck::ui {

using program::RunState;

MachineMdi::MachineMdi(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context), m_starter(new ProgramStarter(this))
{
    m_starter->setStopReason(tr("stopped while the line was checked"));
    connect(m_starter, &ProgramStarter::refused, this, &MachineMdi::onStartRefused);
    connect(m_starter, &ProgramStarter::started, this, [this] { Q_EMIT started(m_current); });
    connect(context, &MachineContext::machineChanged, this, &MachineMdi::onMachineChanged);
    onMachineChanged();
}

MachineMdi::~MachineMdi() = default;

void MachineMdi::onMachineChanged()
{
    machine::Machine* machine = m_context->machine();
    if (m_runner && (m_runnerMachine.isNull() || m_runnerMachine != machine)) {
        m_starter->cancel(tr("the machine was closed")); // ends the line being checked
        delete m_runner;
        m_runner = nullptr;
        if (m_current != 0) // it ran on the machine closed now, which stopped every controller
            end(false, tr("the machine was closed"));
    }
    m_session.reset(); // another machine starts in G-code's defaults
    if (!machine || m_runner)
        return;
    m_runner = new program::ProgramRunner(machine, this);
    m_runner->setOwnerName(tr("an MDI line runs"));
    m_runnerMachine = machine;
    m_runner->setFeedOverride(m_feedOverride);
    connect(m_runner, &program::ProgramRunner::finished, this, &MachineMdi::onFinished);
    connect(m_runner, &program::ProgramRunner::paused, this, [this](int, const QString& text) {
        if (m_runner->pausedAtOperatorStop())
            Q_EMIT paused(m_current, text);
    });
    connect(m_runner, &program::ProgramRunner::operatorMessage, this, &MachineMdi::operatorMessage);
    // A line's G10 sets a coordinate system, as a program's does (LinuxCNC).
    connect(m_runner, &program::ProgramRunner::coordinateSystemSet, m_context->workOffsets(),
            &program::MachineWorkOffsets::setSystem);
}

quint64 MachineMdi::runLine(const QString& line, QString* refusal)
{
    return start(line, true, refusal);
}

quint64 MachineMdi::runOwnLine(const QString& line, QString* refusal)
{
    return start(line, false, refusal);
}

quint64 MachineMdi::start(const QString& line, bool mdi, QString* refusal)
{
    // Another runner holds the machine's motion (a program; Machine::claimMotion).
    const machine::Machine* open = m_context->machine();
    const QString busy =
        open && m_runner && !open->holdsMotion(m_runner) ? open->motionHolder() : QString();
    QString why = !m_runner         ? tr("no machine is open")
                  : isBusy()        ? tr("the last line has not ended")
                  : !busy.isEmpty() ? busy
                                    : QString();
    std::optional<program::Program> program;
    if (why.isEmpty()) {
        QStringList axes;
        for (const machine::MachineAxis& a : m_context->machine()->description().axes)
            axes << a.name;
        QList<program::ProgramError> errors;
        program::MdiSession own;
        program = (mdi ? m_session : own).prepare(line, axes, &errors);
        if (!program && !errors.isEmpty())
            why = errors.first().text();
    }
    if (why.isEmpty()) {
        // In the coordinates and with the tools the position display shows, as a program.
        m_runner->setCoordinateSystems(m_context->workOffsets()->systems(),
                                       m_context->workOffsets()->active());
        m_runner->setToolTable(m_context->tools()->table());
        m_current = ++m_lastId;
        m_currentIsMdi = mdi;
        if (m_starter->request(m_runner, *program, 1, false)) {
            qCDebug(lcMdi) << "line" << m_current << line;
            Q_EMIT busyChanged(true);
            return m_current;
        }
        m_current = 0;
        why = tr("the last line has not ended");
    }
    if (refusal)
        *refusal = why;
    return 0;
}

void MachineMdi::onStartRefused(const QList<program::ProgramError>& errors)
{
    if (m_current == 0)
        return;
    QStringList texts;
    for (const program::ProgramError& e : errors)
        texts << e.message;
    end(false, texts.isEmpty() ? tr("refused") : texts.join(QStringLiteral("; ")));
}

void MachineMdi::onFinished(RunState state, const QString& message)
{
    if (m_current == 0)
        return;
    const bool ok = state == RunState::Finished;
    end(ok, ok ? QString() : message.isEmpty() ? program::runStateText(state) : message);
}

void MachineMdi::end(bool ok, const QString& message)
{
    const quint64 id = std::exchange(m_current, 0);
    if (m_currentIsMdi) {
        // A line that selected G54..G59 makes it the window's active system (LinuxCNC's MDI).
        if (const std::optional<int> system = m_session.lineRan(ok))
            m_context->workOffsets()->setActive(*system);
    }
    Q_EMIT busyChanged(false);
    Q_EMIT ended(id, ok, message);
}

void MachineMdi::setFeedOverride(int percent)
{
    m_feedOverride = percent;
    if (m_runner)
        m_runner->setFeedOverride(percent);
}

void MachineMdi::resume()
{
    if (!m_runner || m_current == 0 || m_runner->state() != RunState::Paused)
        return;
    // An MDI line's M6 with tool lengths by touch-off (issue 50 item 4): nothing of the line
    // cuts after it, and the next line or program takes the work Z as the operator sets it.
    if (m_runner->awaitsTouchOff())
        m_runner->resumeSameTool();
    else
        m_runner->resume();
}

void MachineMdi::abort()
{
    m_starter->cancel(tr("stopped while the line was checked"));
    if (m_runner && m_current != 0 && !program::isEnded(m_runner->state()) &&
        m_runner->state() != RunState::Idle)
        m_runner->abort();
}

bool MachineMdi::isBusy() const
{
    return m_current != 0;
}

bool MachineMdi::isPausedAtOperatorStop() const
{
    return m_current != 0 && m_runner && m_runner->pausedAtOperatorStop();
}

QString MachineMdi::prompt() const
{
    return isPausedAtOperatorStop() ? m_runner->prompt() : QString();
}

} // namespace stepdeck::ui
