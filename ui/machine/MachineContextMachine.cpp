// MachineContext, part 2: a machine of several controllers (issue 19). The core Machine owns
// one session per controller; the context selects one of them for the per-controller pages.
#include "machine/Machine.h"
#include "drives/PositionErrorResetButton.h"
#include "machine/ConnectionMachine.h"
#include "machine/MachineContext.h"
#include "machine/MachineFile.h"
#include "machine/MachineSetup.h"
#include "program/MachineTools.h"
#include "program/MachineWorkOffsets.h"
#include "protocols/Registry.h"
#include <optional>

namespace stepdeck::ui {

bool MachineContext::openMachine(const QString& path, QString* error)
{
    machine::MachineFileError invalid;
    const std::optional<machine::MachineDescription> description =
        machine::MachineFile::load(path, &invalid);
    if (!description) {
        if (error)
            *error = tr("Machine file %1: %2").arg(path, invalid.text());
        return false;
    }
    return openMachine(*description, error, path);
}

bool MachineContext::openMachine(const machine::MachineDescription& description, QString* error,
                                 const QString& path)
{
    // Everything is checked (and every session built) before the open link is touched: an
    // invalid machine leaves what runs now as it is.
    auto created = std::make_unique<machine::Machine>();
    // The core's messages name this window's buttons, not CLI commands (issue 16), as for the
    // connection bar's controller (connectTo).
    ControllerOptions base;
    base.actionNames.insert(PositionErrorResetButton::operationName(),
                            PositionErrorResetButton::actionName());
    created->setBaseOptions(base);
    QString why;
    if (!created->create(description, &why)) {
        if (error)
            *error = tr("Machine \"%1\": %2").arg(description.name, why);
        return false;
    }
    if (!m_machine || m_connectionMachine)
        m_singleModel = m_model;
    install(std::move(created), path, false);
    return true;
}

void MachineContext::uninstall()
{
    for (const QMetaObject::Connection& c : std::as_const(m_relay))
        disconnect(c);
    m_relay.clear();
    m_selected = nullptr;
    m_selectedId.clear();
    m_machinePath.clear();
    if (!m_machine)
        return;
    const std::unique_ptr<machine::Machine> closing = std::move(m_machine);
    closing->disconnect(this);
    closing->destroy(); // every controller's stop, flushed, before its port closes
}

void MachineContext::install(std::unique_ptr<machine::Machine> created, const QString& path,
                             bool connectionMachine)
{
    uninstall();
    m_machine = std::move(created);
    m_connectionMachine = connectionMachine;
    m_machinePath = path;
    const machine::MachineDescription& description = m_machine->description();
    // Before machineChanged: its listeners show them.
    const QString key =
        connectionMachine ? connectionOffsetsKey(description.controllers.first().modelId) : path;
    m_workOffsets->load(key);
    m_tools->load(key);
    connect(m_machine.get(), &machine::Machine::controllerFailed, this,
            &MachineContext::machineControllerFailed);
    connect(m_machine.get(), &machine::Machine::statusChanged, this,
            &MachineContext::machineStatusChanged);
    connect(m_machine.get(), &machine::Machine::spindleAndCoolantOff, this,
            &MachineContext::machineSpindleAndCoolantOff);
    connect(m_machine.get(), &machine::Machine::jogRefused, this,
            &MachineContext::machineJogRefused);
    connect(m_machine->setupWriter(), &machine::MachineSetup::written, this,
            [this](const QString& controllerId, bool ok, const QString& message) {
                // The Setup page's form counts what the device holds: the file's values now.
                if (ok && controllerId == m_selectedId)
                    if (const machine::MachineController* c =
                            m_machine->description().controller(controllerId))
                        addKnownParameters(c->setup);
                Q_EMIT machineSetupWritten(controllerId, ok, message);
            });
    m_model = nullptr; // selectController announces the model, whichever it is
    selectController(description.controllers.first().id);
    Q_EMIT machineChanged();
}

void MachineContext::closeMachine()
{
    if (!m_machine)
        return;
    if (m_connectionMachine) {
        disconnectMachine();
        return;
    }
    openIdleConnectionMachine(m_singleModel);
}

void MachineContext::selectController(const QString& controllerId)
{
    ControllerSession* chosen = m_machine ? m_machine->session(controllerId) : nullptr;
    if (!chosen || chosen == m_selected)
        return;
    if (chosen != m_session) // the connection machine's session is m_session itself
        relayFrom(chosen);
    m_selected = chosen;
    m_selectedId = controllerId;
    m_model = chosen->model();
    forgetKnownParameters(); // they were another controller's
    Q_EMIT modelChanged();
    // Still known: this controller's setup from the machine file, written when its link came
    // up. The written signal (install) counts it only for the controller selected then, so a
    // Setup page chosen later showed the defaults as if nothing were on the device (issue 47,
    // item 9). Not once the board reports its setup incomplete: it may have lost it (power
    // cycle) while another controller was shown.
    const machine::MachineSetup* writer = m_machine->setupWriter();
    const std::optional<CommandResult> setup =
        writer ? writer->lastResult(controllerId) : std::nullopt;
    const machine::MachineController* c = m_machine->description().controller(controllerId);
    if (c && setup && setup->ok() && chosen->isCreated() &&
        chosen->linkState() == LinkState::Connected && !chosen->status().setupIncomplete)
        addKnownParameters(c->setup);
    announceLink();
}

void MachineContext::relayFrom(ControllerSession* selected)
{
    // The panels listen to m_session (they connected to it when they were built); with a
    // machine open it repeats what the selected controller's session says.
    for (const QMetaObject::Connection& c : std::as_const(m_relay))
        disconnect(c);
    m_relay = {
        connect(selected, &ControllerSession::linkStateChanged, m_session,
                &ControllerSession::linkStateChanged),
        connect(selected, &ControllerSession::statusChanged, m_session,
                &ControllerSession::statusChanged),
        connect(selected, &ControllerSession::requestFinished, m_session,
                &ControllerSession::requestFinished),
        connect(selected, &ControllerSession::errorOccurred, m_session,
                &ControllerSession::errorOccurred),
        connect(selected, &ControllerSession::traffic, m_session, &ControllerSession::traffic),
        connect(selected, &ControllerSession::pollRateChanged, m_session,
                &ControllerSession::pollRateChanged),
        connect(selected, &ControllerSession::jogRefused, m_session,
                &ControllerSession::jogRefused),
    };
}

void MachineContext::announceLink()
{
    // Listeners learn the now selected controller's state as if it had just changed (no
    // reason: nothing new happened on that link).
    const ControllerSession* s = session();
    Q_EMIT m_session->linkStateChanged(s->isCreated() ? s->linkState() : LinkState::Disconnected,
                                       QString());
    Q_EMIT m_session->statusChanged(s->status());
}

void MachineContext::connectMachine()
{
    if (m_machine)
        m_machine->open();
}

void MachineContext::disconnectMachine()
{
    if (m_machine)
        m_machine->close();
}

bool MachineContext::machineLinkBusy() const
{
    if (!m_machine)
        return false;
    for (const machine::MachineController& c : m_machine->description().controllers) {
        const LinkState state = m_machine->session(c.id)->linkState();
        if (state == LinkState::Connected || state == LinkState::Connecting)
            return true;
    }
    return false;
}

void MachineContext::endMachineJog()
{
    if (m_machine)
        m_machine->endJog();
}

MachineStatus MachineContext::machineWideStatus(LinkState* link) const
{
    const ControllerSession* selected = session();
    *link = selected->isCreated() ? selected->linkState() : LinkState::Disconnected;
    if (!m_machine)
        return {};
    MachineStatus out = selected->status();
    bool unreported = false;
    for (const machine::MachineController& c : m_machine->description().controllers) {
        const ControllerSession* s = m_machine->session(c.id);
        // Lost is worse than disconnected, disconnected than connecting (Machine::state).
        static const QList<LinkState> kBetterFirst{LinkState::Connected, LinkState::Connecting,
                                                   LinkState::Disconnected, LinkState::Lost};
        if (kBetterFirst.indexOf(s->linkState()) > kBetterFirst.indexOf(*link))
            *link = s->linkState();
        const MachineStatus& st = s->status();
        out.panic = out.panic || st.panic;
        out.setupIncomplete = out.setupIncomplete || st.setupIncomplete;
        out.motionUnconfirmed = out.motionUnconfirmed || st.motionUnconfirmed;
        out.busy = out.busy || st.busy;
        for (auto it = st.axes.cbegin(); it != st.axes.cend(); ++it) {
            if (!out.axes.contains(it.key())) {
                out.axes.insert(it.key(), it.value());
                continue;
            }
            AxisStatus& merged = out.axes[it.key()];
            merged.referenced = merged.referenced && it.value().referenced;
            merged.moving = merged.moving || it.value().moving;
        }
        unreported = unreported || st.axes.isEmpty();
    }
    if (unreported)
        out.axes.clear(); // a controller without a status yet: nothing is "all referenced"
    return out;
}

machine::PositionKnowledge MachineContext::positionKnowledge() const
{
    using machine::PositionKnowledge;
    // Unknown is the worst, then Estimated.
    auto worse = [](PositionKnowledge a, PositionKnowledge b) {
        const auto rank = [](PositionKnowledge k) {
            return k == PositionKnowledge::Unknown ? 2 : k == PositionKnowledge::Estimated ? 1 : 0;
        };
        return rank(a) >= rank(b) ? a : b;
    };
    std::optional<PositionKnowledge> worst;
    if (m_machine) {
        for (const machine::MachineAxis& axis : m_machine->description().axes) {
            const PositionKnowledge k = m_machine->axisStatus(axis).known;
            worst = worst ? worse(*worst, k) : k;
        }
    }
    return worst.value_or(PositionKnowledge::Unknown);
}

} // namespace stepdeck::ui
