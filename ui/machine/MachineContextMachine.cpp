// MachineContext, part 2: a machine of several controllers (issue 19). The core Machine owns
// one session per controller; the context selects one of them for the per-controller pages.
#include "machine/Machine.h"
#include "drives/PositionErrorResetButton.h"
#include "machine/MachineContext.h"
#include "machine/MachineFile.h"
#include "machine/MachineSetup.h"
#include "machine/MachineWorkOffsets.h"
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
    // The core's messages name this window's buttons, not CLI commands (issue 16), as for a
    // single controller (connectTo).
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
    if (m_machine)
        closeMachine();
    else
        m_singleModel = m_model;
    if (m_session->isCreated())
        m_session->destroy(); // the single controller's stop, flushed, then its port closed
    m_machine = std::move(created);
    m_machinePath = path;
    m_workOffsets->load(path); // before machineChanged: its listeners show them
    connect(m_machine.get(), &machine::Machine::controllerFailed, this,
            &MachineContext::machineControllerFailed);
    connect(m_machine.get(), &machine::Machine::statusChanged, this,
            &MachineContext::machineStatusChanged);
    connect(m_machine->setupWriter(), &machine::MachineSetup::written, this,
            [this](const QString& controllerId, bool ok, const QString& message) {
                // The Setup page's form counts what the device holds: the file's values now.
                if (ok && controllerId == m_selectedId)
                    if (const machine::MachineController* c =
                            m_machine->description().controller(controllerId))
                        addKnownParameters(c->setup);
                Q_EMIT machineSetupWritten(controllerId, ok, message);
            });
    selectController(description.controllers.first().id);
    Q_EMIT machineChanged();
    return true;
}

void MachineContext::closeMachine()
{
    if (!m_machine)
        return;
    for (const QMetaObject::Connection& c : std::as_const(m_relay))
        disconnect(c);
    m_relay.clear();
    m_selected = nullptr;
    m_selectedId.clear();
    m_machinePath.clear();
    m_workOffsets->load(QString());
    const std::unique_ptr<machine::Machine> closing = std::move(m_machine);
    closing->disconnect(this);
    closing->destroy(); // every controller's stop, flushed, before its port closes
    m_model = m_singleModel;
    loadUnits();
    loadSoftLimits();
    forgetKnownParameters();
    Q_EMIT modelChanged();
    Q_EMIT machineChanged();
    announceLink();
}

void MachineContext::selectController(const QString& controllerId)
{
    ControllerSession* chosen = m_machine ? m_machine->session(controllerId) : nullptr;
    if (!chosen || chosen == m_selected)
        return;
    relayFrom(chosen);
    m_selected = chosen;
    m_selectedId = controllerId;
    m_model = chosen->model();
    loadUnits();
    m_softLimits = chosen->softLimits(); // the file's, in steps (Machine)
    forgetKnownParameters();             // they were another controller's
    Q_EMIT modelChanged();
    Q_EMIT softLimitsChanged();
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
        return selected->status();
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
        return worst.value_or(PositionKnowledge::Unknown);
    }
    const ControllerSession* s = session();
    if (!s->isCreated() || s->linkState() != LinkState::Connected)
        return PositionKnowledge::Unknown;
    // As Machine::axisStatus judges a controller axis.
    for (const AxisStatus& a : s->status().axes) {
        const PositionKnowledge k = !a.positionKnown ? PositionKnowledge::Unknown
                                    : (a.positionEstimated || a.motionUnknown)
                                        ? PositionKnowledge::Estimated
                                        : PositionKnowledge::Referenced;
        worst = worst ? worse(*worst, k) : k;
    }
    return worst.value_or(PositionKnowledge::Unknown);
}

machine::MachineDescription
MachineContext::connectedControllerMachine(QMap<QString, double>* workOffsets) const
{
    const ConnectionSpec& spec = m_session->spec();
    const ModelInfo& model = *m_model;
    QMap<Axis, int> addresses;
    if (model.capabilities.multiDrive)
        addresses = spec.options.axisAddresses;
    machine::MachineDescription d =
        machine::MachineDescription::singleController(model, m_port, addresses);
    if (model.capabilities.resetLine)
        d.controllers.first().resetLine = spec.options.resetLine;
    for (machine::MachineAxis& a : d.axes) {
        // The Referencing panel's order and direction (a skipped axis keeps its order: the
        // machine references every axis it has).
        a.referenceOrder = referenceOrder(a.axis);
        const int direction = referenceDirection(a.axis);
        if (model.capabilities.referenceDirection && (direction == -1 || direction == 1))
            a.referenceDirection = direction;
        const AxisUnits u = m_units.value(a.axis);
        if (u.stepsPerUnit <= 0)
            continue; // steps, as the controller counts
        const bool inch = u.unit == QLatin1String("in");
        a.unit = u.unit == QStringLiteral("\u00b0") ? machine::AxisUnit::Degree
                                                    : machine::AxisUnit::Millimetre;
        a.stepsPerUnit = inch ? u.stepsPerUnit / 25.4 : u.stepsPerUnit;
        const AxisSoftLimit limit = m_softLimits.limit(a.axis);
        if (limit.enabled && limit.rangeSet) {
            a.softMinimum = a.toUnits(limit.minimum);
            a.softMaximum = a.toUnits(limit.maximum);
        }
        if (workOffsets && u.workOffset != 0)
            workOffsets->insert(a.name, a.toUnits(u.workOffset));
    }
    if (workOffsets) // an axis in steps keeps its origin in steps
        for (const machine::MachineAxis& a : d.axes)
            if (a.unit == machine::AxisUnit::Step && m_units.value(a.axis).workOffset != 0)
                workOffsets->insert(a.name, double(m_units.value(a.axis).workOffset));
    return d;
}

bool MachineContext::openConnectedControllerAsMachine(QString* error)
{
    if (!m_model || !m_session->isCreated() || m_machine)
        return false;
    QMap<QString, double> offsets;
    const machine::MachineDescription d = connectedControllerMachine(&offsets);
    if (!openMachine(d, error))
        return false;
    for (auto it = offsets.cbegin(); it != offsets.cend(); ++it)
        m_workOffsets->set(it.key(), it.value());
    connectMachine(); // the same port, now the machine's controller
    return true;
}

} // namespace stepdeck::ui
