#include "CliMachineSession.h"
#include "CliCommands.h"
#include "CliText.h"
#include "machine/MachineSetup.h"
#include "machine/MachineSwitchOff.h"
#include "protocols/Registry.h"
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <climits>

namespace stepdeck::cli {

using machine::Machine;
using machine::MachineController;

CliMachineSession::CliMachineSession(const CliOptions& options,
                                     const machine::MachineDescription& description,
                                     QObject* parent)
    : QObject(parent), m_options(options), m_description(description)
{
    m_machine.setBaseOptions(CliSession::baseControllerOptions(options));
    connect(&m_machine, &Machine::statusChanged, this, [this] { wake(); });
    connect(&m_machine, &Machine::moveFinished, this, [this] { wake(); });
    connect(&m_machine, &Machine::referenceFinished, this, [this] { wake(); });
    connect(&m_machine, &Machine::controllerFailed, this,
            [this](const QString& id, const QString& message) {
                // Only a lost link makes the whole command a link failure; a refused or
                // failed part is the move's own outcome.
                const ControllerSession* s = m_machine.session(id);
                if (m_connected && s && s->linkState() != LinkState::Connected &&
                    m_lostController.isEmpty()) {
                    m_lostController = id;
                    m_lostMessage = message;
                }
                wake();
            });
}

void CliMachineSession::wake()
{
    m_wait.wake();
}

bool CliMachineSession::waitFor(const std::function<bool()>& done, int timeoutMs)
{
    return m_wait.waitFor(done, timeoutMs, m_interrupted);
}

bool CliMachineSession::pause(int ms)
{
    waitFor([] { return false; }, ms);
    return !m_interrupted;
}

void CliMachineSession::watchSessions()
{
    for (const MachineController& c : m_description.controllers) {
        ControllerSession* s = m_machine.session(c.id);
        connect(s, &ControllerSession::requestFinished, this,
                [this, id = c.id](const CommandResult& r) {
                    if (r.id == 0)
                        return;
                    m_finished[id].insert(r.id, r);
                    if (!r.ok())
                        m_lastFailure = r.error;
                    wake();
                });
        connect(s, &ControllerSession::errorOccurred, this, [this, c](const QString& message) {
            // What a controller did or saw on its own (the E-LAB adapter stopping motion it did
            // not command): a read reports it with what it read. Kept from the link's opening
            // on: the adapter's first status read, which may already see that motion, runs
            // before the link counts as connected (dropping it then lost the note under load).
            const QString note = faultText(c, message);
            if (!m_notes.contains(note))
                m_notes << note;
        });
        connect(s, &ControllerSession::jogRefused, this, [this, id = c.id](const QString& reason) {
            if (m_jogRefusal.isEmpty())
                m_jogRefusal = m_description.controllers.size() == 1
                                   ? reason
                                   : CliText::tr("controller \"%1\": %2").arg(id, reason);
            wake();
        });
        connect(s, &ControllerSession::linkStateChanged, this,
                [this, id = c.id](LinkState state, const QString& reason) {
                    if (m_connected && state != LinkState::Connected && !reason.isEmpty())
                        m_lostReasons.insert(id, reason);
                    wake();
                });
    }
}

// A machine of one controller (--model/--port) names its port as a single controller
// always did; on a machine of several the controller is named too.
QString CliMachineSession::faultText(const MachineController& c, const QString& message) const
{
    if (m_description.controllers.size() != 1)
        return CliText::tr("controller \"%1\" (%2): %3").arg(c.id, c.port, message);
    return message.contains(c.port) ? message : CliText::tr("%1: %2").arg(c.port, message);
}

Outcome CliMachineSession::openAll()
{
    QMap<QString, RequestId> opened; // each session's own open, for its failure's reason
    for (const MachineController& c : m_description.controllers)
        opened.insert(c.id, m_machine.session(c.id)->open());
    const auto settled = [&] { // every link up, or one failed for good
        bool allUp = true;
        for (const MachineController& c : m_description.controllers) {
            const LinkState state = m_machine.session(c.id)->linkState();
            const auto finished = m_finished.value(c.id).constFind(opened.value(c.id));
            if (state == LinkState::Lost ||
                (finished != m_finished.value(c.id).cend() && !finished->ok()))
                return true;
            allUp = allUp && state == LinkState::Connected;
        }
        return allUp;
    };
    waitFor(settled, m_options.connectTimeoutMs);
    if (m_interrupted)
        return Outcome::failure(ExitInterrupted, CliText::tr("interrupted"));
    // The controller that failed is named first; a slower one still connecting is not at fault.
    for (const MachineController& c : m_description.controllers) {
        const CommandResult r = m_finished[c.id].take(opened.value(c.id));
        if (r.id != 0 && !r.ok())
            return Outcome::failure(exitCodeFor(r.error), faultText(c, r.message));
    }
    for (const MachineController& c : m_description.controllers) {
        if (m_machine.session(c.id)->linkState() != LinkState::Connected)
            return Outcome::failure(
                ExitLinkDown,
                faultText(c, CliText::tr("no connection within %1 ms (powered, cabled, right "
                                         "model?)")
                                 .arg(m_options.connectTimeoutMs)));
    }
    return Outcome::success();
}

void CliMachineSession::setReferenceDirections(const QMap<QString, int>& directions)
{
    for (machine::MachineAxis& a : m_description.axes) {
        if (directions.contains(a.name))
            a.referenceDirection = directions.value(a.name);
    }
}

Outcome CliMachineSession::connectAll()
{
    if (m_connected)
        return Outcome::success();
    QString error;
    if (!m_machine.create(m_description, &error))
        return Outcome::usage(error);
    watchSessions();
    if (const Outcome opened = openAll(); !opened.ok())
        return opened;
    if (const Outcome setup = awaitMachineSetup(); !setup.ok())
        return setup;
    m_connected = true;
    if (m_options.setupDefaults) {
        if (const Outcome written = writeSetupDefaults(); !written.ok())
            return written;
    }
    QMap<QString, RequestId> refreshes;
    for (const MachineController& c : m_description.controllers)
        refreshes.insert(c.id, m_machine.session(c.id)->refreshStatus());
    const Outcome refreshed = waitAll(refreshes, CliSession::kRequestTimeoutMs);
    m_lastFailure = ErrorKind::None; // from here on: the command's own requests
    return refreshed;
}

// The machine file's setups (controllers[i].setup), written by MachineSetup as the links came
// up: a command runs on a machine set as its file says, or not at all.
Outcome CliMachineSession::awaitMachineSetup()
{
    const machine::MachineSetup* setup = m_machine.setupWriter();
    if (!setup)
        return Outcome::success();
    for (const MachineController& c : m_description.controllers) {
        if (c.setup.isEmpty())
            continue;
        waitFor([&] { return setup->lastResult(c.id).has_value(); }, CliSession::kRequestTimeoutMs);
        const std::optional<CommandResult> r = setup->lastResult(c.id);
        if (!r)
            return Outcome::failure(
                ExitTimeout, CliText::tr("controller \"%1\": its setup from %2 was not confirmed "
                                         "within %3 ms")
                                 .arg(c.id, c.setupFile)
                                 .arg(CliSession::kRequestTimeoutMs));
        if (!r->ok())
            return Outcome::failure(exitCodeFor(r->error),
                                    CliText::tr("controller \"%1\": writing its setup from %2 "
                                                "failed: %3")
                                        .arg(c.id, c.setupFile, r->message));
    }
    return Outcome::success();
}

// --setup-defaults on every controller, as CliContext::connect() does for one.
Outcome CliMachineSession::writeSetupDefaults()
{
    QMap<QString, RequestId> writes;
    for (const MachineController& c : m_description.controllers) {
        ControllerSession* s = m_machine.session(c.id);
        const ParameterSet defaults = unattendedDefaults(*s->model(), s->capabilities().axes);
        writes.insert(c.id, s->writeParameters(defaults, canVerify(*s->model(), defaults)));
    }
    Outcome result = waitAll(writes, CliSession::kRequestTimeoutMs);
    if (!result.ok())
        result.message = CliText::tr("--setup-defaults: %1").arg(result.message);
    return result;
}

CommandResult CliMachineSession::waitResult(const QString& controllerId, RequestId id,
                                            int timeoutMs)
{
    const ControllerSession* s = m_machine.session(controllerId);
    waitFor(
        [&] {
            return m_finished.value(controllerId).contains(id) ||
                   s->linkState() != LinkState::Connected;
        },
        timeoutMs);
    if (m_finished[controllerId].contains(id))
        return verdict(controllerId, m_finished[controllerId].take(id));
    if (s->linkState() != LinkState::Connected)
        return CommandResult::failure(id, ErrorKind::LinkDown, CliText::tr("link lost"));
    if (m_interrupted)
        return CommandResult::failure(id, ErrorKind::Cancelled, CliText::tr("interrupted"));
    return CommandResult::failure(
        id, ErrorKind::Timeout,
        CliText::tr("no result from the controller within %1 ms").arg(timeoutMs));
}

// One fault, one exit code (as CliSession::call): a request that timed out while the
// controller stopped answering altogether is the lost link the poller is about to declare.
CommandResult CliMachineSession::verdict(const QString& controllerId, const CommandResult& r)
{
    const ErrorKind e = r.error;
    if (!m_connected || m_interrupted ||
        (e != ErrorKind::Timeout && e != ErrorKind::Cancelled && e != ErrorKind::Protocol))
        return r;
    waitFor([this] { return linkLost(); },
            CliSession::linkVerdictMs(m_machine.session(controllerId)->spec().options));
    if (!linkLost())
        return r;
    return CommandResult::failure(r.id, ErrorKind::LinkDown, linkLostOutcome().message);
}

Outcome CliMachineSession::waitAll(const QMap<QString, RequestId>& ids, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    Outcome first = Outcome::success();
    for (auto it = ids.cbegin(); it != ids.cend(); ++it) {
        const int left = int(qMax<qint64>(0, timeoutMs - clock.elapsed()));
        const CommandResult r = waitResult(it.key(), it.value(), left);
        if (!r.ok() && first.ok())
            first = Outcome::failure(
                exitCodeFor(r.error),
                m_description.controllers.size() == 1
                    ? r.message
                    : CliText::tr("controller \"%1\": %2").arg(it.key(), r.message));
    }
    if (!first.ok() && linkLost())
        return linkLostOutcome();
    return first;
}

Outcome CliMachineSession::linkLostOutcome() const
{
    // One controller: its link, as a single controller always said it.
    QString why = m_description.controllers.size() == 1 && m_lostReasons.contains(m_lostController)
                      ? CliText::tr("link lost: %1").arg(m_lostReasons.value(m_lostController))
                      : m_lostMessage;
    const ControllerSession* s = m_machine.session(m_lostController);
    if (s && s->status().motionUnconfirmed)
        why = CliText::tr("%1; %2").arg(why, Controller::mayStillBeMovingText());
    return Outcome::failure(ExitLinkDown, why);
}

Outcome CliMachineSession::motionFailure(const QString& message) const
{
    if (linkLost())
        return linkLostOutcome();
    if (m_lastFailure != ErrorKind::None)
        return Outcome::failure(exitCodeFor(m_lastFailure), message);
    return Outcome::failure(ExitMotionAborted, message);
}

void CliMachineSession::signal(int signalNumber)
{
    if (m_programSignals && m_programSignals(signalNumber)) {
        wake();
        return;
    }
    interrupt();
}

void CliMachineSession::interrupt()
{
    m_interrupted = true;
    wake();
}

Outcome CliMachineSession::stopAll()
{
    if (!m_connected)
        return Outcome::success();
    const bool wasInterrupted = std::exchange(m_interrupted, false); // let the waits run
    // Both at once: the jog's ramp and the model's stop go to every controller before any
    // answer is awaited (a slow link never holds back another controller's stop).
    m_machine.endJog();
    QMap<QString, RequestId> ids = m_machine.stop();
    for (auto it = ids.begin(); it != ids.end();) {
        // A controller without a stop command answers with its own refusal, which says what
        // to do instead (the emergency stop); one whose link is down has nothing to stop.
        if (m_machine.session(it.key())->linkState() != LinkState::Connected)
            it = ids.erase(it);
        else
            ++it;
    }
    const Outcome result = waitAll(ids, kStopWaitMs);
    // Spindle and coolant go off once the axes stand (Machine::stop, issue 47): the command
    // waits for the controllers' acknowledgements, so the process never ends with them on
    // unsaid.
    QString switchOffFailure;
    QObject guard;
    connect(&m_machine, &Machine::spindleAndCoolantOff, &guard,
            [this, &switchOffFailure](bool ok, const QString& message) {
                if (!ok)
                    switchOffFailure = message;
                wake();
            });
    if (m_machine.isSwitchingOff())
        waitFor([this] { return !m_machine.isSwitchingOff(); },
                machine::MachineSwitchOff::kWaitMs + 1000);
    if (!switchOffFailure.isEmpty())
        printError(switchOffFailure);
    m_interrupted = wasInterrupted;
    return result;
}

} // namespace stepdeck::cli
