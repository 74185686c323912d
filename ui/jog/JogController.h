#pragma once
#include "model/Axis.h"
#include <QHash>
#include <QObject>
#include <QTimer>

namespace stepdeck::ui {

class JogInputSource;
class MachineContext;
class TargetJogger;

// Combines every jog input into per-axis velocities and sends them to the controller
// session. While any axis is deflected it renews the core's jog lease every kRenewMs; when
// all inputs are released it sends zero targets and endJog(), and the core JogRamp ramps the
// axes down. The ramp itself lives in the core, never here.
class JogController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kRenewMs = 75;

    explicit JogController(MachineContext* context, QObject* parent = nullptr);

    // Per axis the largest magnitude over all sources wins.
    void setDeflection(const QObject* source, const AxisVelocities& fractions);
    void release(const QObject* source);
    void addSource(JogInputSource* source);

    void setMaxSpeed(Axis axis, double stepsPerS);
    double maxSpeed(Axis axis) const;
    double maxSpeedCeiling() const;
    void setOverride(double fraction); // 0..1, scales every jog speed
    double override() const { return m_override; }

    AxisVelocities targets() const { return m_targets; }
    // Controllers without a jog command (Capabilities::jogByTargets) jog through this.
    TargetJogger* targetJogger() const { return m_targetJog; }
    bool isJogging() const;

public Q_SLOTS:
    // Everything to zero at once (focus loss, STOP, PANIC, link loss).
    void releaseAll();

Q_SIGNALS:
    void refused(const QString& reason);
    void targetsChanged(const stepdeck::AxisVelocities& targets);

private:
    void update();
    void send();
    void loadSettings();
    QString refusal() const;

    MachineContext* m_context;
    TargetJogger* m_targetJog;
    QHash<const QObject*, AxisVelocities> m_inputs;
    QMap<Axis, double> m_maxSpeed;
    double m_override = 1.0;
    AxisVelocities m_targets;
    bool m_active = false;
    QString m_lastRefusal;
    QTimer m_renew;
};

} // namespace stepdeck::ui
