#include "JogController.h"
#include "jog/JogInputSource.h"
#include "jog/TargetJogger.h"
#include "main/MachineContext.h"
#include <QSettings>
#include <QtMath>

namespace stepdeck::ui {

JogController::JogController(MachineContext* context, QObject* parent)
    : QObject(parent), m_context(context), m_targetJog(new TargetJogger(context->session(), this))
{
    connect(m_targetJog, &TargetJogger::refused, this, [this](const QString& reason) {
        m_lastRefusal = reason;
        Q_EMIT refused(reason);
    });
    m_renew.setInterval(kRenewMs);
    connect(&m_renew, &QTimer::timeout, this, &JogController::send);
    connect(context, &MachineContext::modelChanged, this, [this] {
        releaseAll();
        loadSettings();
    });
    ControllerSession* session = context->session();
    connect(session, &ControllerSession::jogRefused, this, [this](const QString& reason) {
        m_lastRefusal = reason;
        Q_EMIT refused(reason);
    });
    connect(session, &ControllerSession::linkStateChanged, this, [this](LinkState state) {
        if (state != LinkState::Connected)
            releaseAll();
    });
    connect(context, &MachineContext::panicTriggered, this, &JogController::releaseAll);
    loadSettings();
}

void JogController::addSource(JogInputSource* source)
{
    connect(source, &JogInputSource::deflectionChanged, this,
            [this, source](const AxisVelocities& f) { setDeflection(source, f); });
    connect(source, &QObject::destroyed, this, [this, source] { release(source); });
}

void JogController::setDeflection(const QObject* source, const AxisVelocities& fractions)
{
    AxisVelocities clean;
    for (auto it = fractions.cbegin(); it != fractions.cend(); ++it) {
        if (it.value() != 0.0)
            clean.insert(it.key(), qBound(-1.0, it.value(), 1.0));
    }
    if (clean.isEmpty())
        m_inputs.remove(source);
    else
        m_inputs.insert(source, clean);
    update();
}

void JogController::release(const QObject* source)
{
    if (m_inputs.remove(source))
        update();
}

void JogController::releaseAll()
{
    const bool wasActive = m_active;
    m_inputs.clear();
    m_targets.clear();
    m_active = false;
    m_renew.stop();
    m_targetJog->release();
    if (wasActive) {
        m_context->session()->endJog();
        Q_EMIT targetsChanged(m_targets);
    }
}

double JogController::maxSpeedCeiling() const
{
    return m_context->capabilities().maxJogSpeed;
}

void JogController::setMaxSpeed(Axis axis, double stepsPerS)
{
    const double value = qBound(1.0, stepsPerS, maxSpeedCeiling());
    m_maxSpeed.insert(axis, value);
    QSettings().setValue(
        QStringLiteral("jog/%1/%2/maxSpeed").arg(m_context->modelId(), axisName(axis)), value);
    update();
}

double JogController::maxSpeed(Axis axis) const
{
    return m_maxSpeed.value(axis, qMin(1000.0, maxSpeedCeiling()));
}

void JogController::setOverride(double fraction)
{
    m_override = qBound(0.0, fraction, 1.0);
    update();
}

bool JogController::isJogging() const
{
    return m_active;
}

void JogController::loadSettings()
{
    m_maxSpeed.clear();
    const QSettings settings;
    const double fallback = qMin(1000.0, maxSpeedCeiling());
    for (Axis axis : m_context->axes()) {
        const QString key =
            QStringLiteral("jog/%1/%2/maxSpeed").arg(m_context->modelId(), axisName(axis));
        m_maxSpeed.insert(axis, qBound(1.0, settings.value(key, fallback).toDouble(),
                                       qMax(1.0, maxSpeedCeiling())));
    }
}

QString JogController::refusal() const
{
    if (!m_context->isConnected())
        return tr("Jog refused: not connected");
    if (m_context->status().panic)
        return tr("Jog refused: emergency stop is active");
    return {};
}

void JogController::update()
{
    AxisVelocities targets;
    for (Axis axis : m_context->axes()) {
        double fraction = 0.0;
        for (const AxisVelocities& input : std::as_const(m_inputs)) {
            const double f = input.value(axis, 0.0);
            if (qAbs(f) > qAbs(fraction))
                fraction = f;
        }
        const double v = fraction * maxSpeed(axis) * m_override;
        if (v != 0.0)
            targets.insert(axis, double(qRound64(v)));
    }
    if (targets.isEmpty()) {
        m_lastRefusal.clear();
        if (m_active) {
            m_active = false;
            m_renew.stop();
            m_targetJog->release();
            AxisVelocities zeros;
            for (Axis axis : m_context->axes())
                zeros.insert(axis, 0.0);
            m_context->session()->setJogVelocity(zeros);
            m_context->session()->endJog();
        }
        if (!m_targets.isEmpty()) {
            m_targets.clear();
            Q_EMIT targetsChanged(m_targets);
        }
        return;
    }
    const QString why = refusal();
    if (!why.isEmpty()) {
        // Not sent at all; the operator sees the reason next to the pad.
        if (m_active)
            releaseAll();
        if (why != m_lastRefusal) {
            m_lastRefusal = why;
            Q_EMIT refused(why);
        }
        return;
    }
    m_lastRefusal.clear();
    // Axes no longer deflected get an explicit zero so they ramp down.
    AxisVelocities full;
    for (Axis axis : m_context->axes())
        full.insert(axis, targets.value(axis, 0.0));
    const bool changed = full != m_targets;
    m_targets = full;
    m_active = true;
    if (changed) {
        send();
        Q_EMIT targetsChanged(m_targets);
    }
    if (!m_renew.isActive())
        m_renew.start();
}

void JogController::send()
{
    if (!m_active)
        return;
    if (m_context->capabilities().jogByTargets)
        m_targetJog->setVelocities(m_targets); // short targets, one after the other
    else
        m_context->session()->setJogVelocity(m_targets);
}

} // namespace stepdeck::ui
