#include "JogController.h"
#include "jog/JogAxisMap.h"
#include "jog/JogInputSource.h"
#include "machine/Machine.h"
#include "machine/MachineContext.h"
#include <QGuiApplication>
#include <QtMath>

namespace stepdeck::ui {

JogController::JogController(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context), m_map(new JogAxisMap(context, this))
{
    // Other axes on the slots: what is held would move another axis, so it moves nothing.
    connect(m_map, &JogAxisMap::changed, this, &JogController::releaseAll);
    m_renew.setInterval(kRenewMs);
    connect(&m_renew, &QTimer::timeout, this, [this] { update(true); });
    connect(context, &MachineContext::modelChanged, this, &JogController::releaseAll);
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::jogRefused, this, [this](const QString& reason) {
        // The core refuses for the same reason the status shows (emergency stop), or its own.
        noteRefusal(reason, panicActive() ? RefusalCause::Panic : RefusalCause::Other);
    });
    connect(context, &MachineContext::machineJogRefused, this,
            [this](const QString&, const QString& reason) {
                noteRefusal(reason, RefusalCause::Other);
            });
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected)
            releaseAll();
        checkRefusalCause();
    });
    connect(session, &ControllerSession::statusChanged, this, &JogController::checkRefusalCause);
    connect(context, &MachineContext::machineStatusChanged, this,
            &JogController::checkRefusalCause);
    connect(context, &MachineContext::panicTriggered, this, &JogController::releaseAll);
    connect(qGuiApp, &QGuiApplication::applicationStateChanged, this,
            [this](Qt::ApplicationState state) {
                if (state != Qt::ApplicationActive)
                    releaseAll();
            });
}

void JogController::addSource(JogInputSource* source)
{
    m_sources.append(source);
    connect(source, &JogInputSource::changed, this, [this] { update(); });
    connect(source, &QObject::destroyed, this, [this] { update(); });
}

QList<JogInputSource*> JogController::sources() const
{
    QList<JogInputSource*> out;
    for (const QPointer<JogInputSource>& s : m_sources) {
        if (s)
            out << s.data();
    }
    return out;
}

void JogController::releaseAll()
{
    if (m_releasing)
        return;
    m_releasing = true; // latching makes sources emit changed(): not a new deflection
    for (JogInputSource* source : sources())
        source->latch();
    m_releasing = false;
    const bool wasActive = m_active;
    m_targets.clear();
    m_active = false;
    m_renew.stop();
    if (wasActive) {
        endJog();
        Q_EMIT targetsChanged(m_targets);
    }
}

void JogController::setMaxSpeed(JogSlot slot, double unitsPerSecond)
{
    m_map->setMaxSpeed(slot, unitsPerSecond);
    Q_EMIT speedSettingsChanged();
    update();
}

double JogController::maxSpeed(JogSlot slot) const
{
    return m_map->maxSpeed(slot);
}

void JogController::setOverride(double fraction)
{
    m_override = qBound(0.0, fraction, 1.0);
    Q_EMIT speedSettingsChanged();
    update();
}

bool JogController::isJogging() const
{
    return m_active;
}

QString JogController::refusal() const
{
    if (!m_context->isConnected())
        return tr("Jog refused: not connected");
    if (panicActive())
        return tr("Jog refused: emergency stop is active");
    return {};
}

bool JogController::panicActive() const
{
    // With a machine open: an emergency stop on any of its controllers.
    LinkState link = LinkState::Disconnected;
    return m_context->machineWideStatus(&link).panic;
}

void JogController::noteRefusal(const QString& reason, RefusalCause cause)
{
    m_lastRefusal = reason;
    m_refusalCause = cause;
    Q_EMIT refused(reason);
}

void JogController::checkRefusalCause()
{
    // A refusal stays on screen while its cause holds, and not after (issue 16): "emergency
    // stop is active" ends with the emergency stop, "not connected" with the new link.
    // Other refusals (a limit switch, a soft limit) end when jogging works again or expire.
    const bool ended =
        (m_refusalCause == RefusalCause::Panic && m_context->isConnected() && !panicActive()) ||
        (m_refusalCause == RefusalCause::NotConnected && m_context->isConnected());
    if (!ended)
        return;
    m_refusalCause = RefusalCause::None;
    m_lastRefusal.clear();
    Q_EMIT refusalEnded();
}

SlotVelocities JogController::provenTargets()
{
    // Focus loss stops jogging: no StepDeck window active, no source counts as held.
    if (QGuiApplication::applicationState() != Qt::ApplicationActive)
        return {};
    QList<SlotVelocities> inputs;
    for (JogInputSource* source : sources())
        inputs << source->heldDeflection();
    SlotVelocities targets;
    for (JogSlot slot : m_map->jogSlots()) {
        double fraction = 0.0;
        for (const SlotVelocities& input : std::as_const(inputs)) {
            const double f = qBound(-1.0, input.value(slot, 0.0), 1.0);
            if (qAbs(f) > qAbs(fraction))
                fraction = f;
        }
        const double v = fraction * maxSpeed(slot) * m_override;
        // Unit/s; Machine::jog makes them the nearest step rate.
        if (v != 0.0)
            targets.insert(slot, v);
    }
    return targets;
}

void JogController::stopSending()
{
    m_lastRefusal.clear();
    if (m_active) {
        m_active = false;
        m_renew.stop();
        endJog();
    }
    if (!m_targets.isEmpty()) {
        m_targets.clear();
        Q_EMIT targetsChanged(m_targets);
    }
}

void JogController::update(bool renewal)
{
    if (m_releasing)
        return;
    // Reading a proof can end a drag (a lost mouse release), which reports a change from
    // inside this call: run again afterwards instead of nesting.
    if (m_updating) {
        m_updateAgain = true;
        return;
    }
    m_updating = true;
    do {
        m_updateAgain = false;
        updateOnce(renewal);
        renewal = false;
    } while (m_updateAgain && !m_releasing);
    m_updating = false;
}

void JogController::updateOnce(bool renewal)
{
    const SlotVelocities targets = provenTargets();
    if (targets.isEmpty()) {
        stopSending();
        return;
    }
    const QString why = refusal();
    if (!why.isEmpty()) {
        // Not sent at all; the operator sees the reason next to the pad.
        if (m_active)
            releaseAll();
        if (why != m_lastRefusal)
            noteRefusal(why, m_context->isConnected() ? RefusalCause::Panic
                                                      : RefusalCause::NotConnected);
        return;
    }
    m_lastRefusal.clear();
    m_refusalCause = RefusalCause::None;
    // Slots no longer deflected get an explicit zero so they ramp down.
    SlotVelocities full;
    for (JogSlot slot : m_map->jogSlots())
        full.insert(slot, targets.value(slot, 0.0));
    const bool changed = full != m_targets;
    m_targets = full;
    m_active = true;
    if (changed || renewal) {
        // Renews the lease with what was just proven (controllers without a jog command get
        // short targets from the machine, the next one only while the input is still proven
        // held).
        if (!sendToMachine())
            return;
    }
    if (changed)
        Q_EMIT targetsChanged(m_targets);
    if (!m_renew.isActive())
        m_renew.start();
}

bool JogController::sendToMachine()
{
    // A machine jogs its axes in their units, within their maxJogSpeed, every controller on
    // this one call (issue 19). A refusal sends nothing: the input counts as released until
    // let go.
    QString why = tr("Jog refused: no machine");
    if (m_context->machine() && m_context->machine()->jog(m_map->machineRates(m_targets), &why))
        return true;
    releaseAll();
    noteRefusal(why, RefusalCause::Other);
    return false;
}

void JogController::endJog()
{
    m_context->endMachineJog();
}

} // namespace stepdeck::ui
