#pragma once
#include "jog/JogSlot.h"
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace stepdeck::ui {

class JogAxisMap;
class JogInputSource;
class MachineContext;

// Combines every jog input into per-slot velocities and sends them to the controller
// session. The core's jog lease (ControllerOptions::jogLeaseMs) is renewed only with proof:
// every kRenewMs the controller asks each source what it can prove is still held
// (JogInputSource::heldDeflection()) and sends only that; a source without fresh proof
// contributes zero, so a lost key-up, mouse release or gamepad sample ends in a ramp to zero
// like a release. When nothing is held it sends zero targets and endJog(); the core JogRamp
// ramps the axes down. The ramp itself lives in the core, never here.
// Jog runs only while a StepDeck window is the active window (focus loss stops jogging).
// The sources speak of jog slots (JogAxisMap): the machine's named axes in unit/s (every
// connection is a machine, issue 28 item 0), every controller jogged through one
// Machine::jog call so that one lost input stops them all.
class JogController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kRenewMs = 75;

    explicit JogController(MachineContext* context, QObject* parent = nullptr);

    // Per slot the largest magnitude over all sources wins.
    void addSource(JogInputSource* source);
    QList<JogInputSource*> sources() const;

    // Per jog slot, in the slot's machine axis' unit/s (JogAxisMap::maxSpeed).
    void setMaxSpeed(JogSlot slot, double unitsPerSecond);
    double maxSpeed(JogSlot slot) const;
    JogAxisMap* axisMap() const { return m_map; }
    void setOverride(double fraction); // 0..1, scales every jog speed
    double override() const { return m_override; }

    SlotVelocities targets() const { return m_targets; }
    bool isJogging() const;

public Q_SLOTS:
    // STOP, PANIC, focus loss, link loss: every target to zero at once, and every source is
    // latched: what is held now moves nothing until it has been released (rule 4).
    void releaseAll();

Q_SIGNALS:
    void refused(const QString& reason);
    // The cause of the last refusal has ended (emergency stop released, link back): whatever
    // shows it is to be cleared.
    void refusalEnded();
    void targetsChanged(const stepdeck::ui::SlotVelocities& targets);
    void speedSettingsChanged(); // a max speed or the override changed

private:
    // Reads every source's proof and sends what changed; renewal: send even if unchanged
    // (this renews the core lease, and only with what was just proven).
    void update(bool renewal = false);
    void updateOnce(bool renewal);
    SlotVelocities provenTargets();
    void stopSending();
    bool sendToMachine(); // false: refused, every input released
    void endJog();
    QString refusal() const;
    bool panicActive() const;
    enum class RefusalCause { None, NotConnected, Panic, Other };
    void noteRefusal(const QString& reason, RefusalCause cause);
    void checkRefusalCause();

    MachineContext* m_context;
    JogAxisMap* m_map;
    QList<QPointer<JogInputSource>> m_sources;
    double m_override = 1.0;
    SlotVelocities m_targets;
    bool m_active = false;
    bool m_releasing = false;
    bool m_updating = false;
    bool m_updateAgain = false;
    QString m_lastRefusal;
    RefusalCause m_refusalCause = RefusalCause::None;
    QTimer m_renew;
};

} // namespace stepdeck::ui
