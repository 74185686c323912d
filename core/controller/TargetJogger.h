#pragma once
#include "controller/ControllerSession.h"
#include <QObject>

namespace stepdeck {

// Jog for controllers without a jog command (Capabilities::jogByTargets, laser motor axes):
// while an input is deflected, each axis gets a short relative target -- the distance the
// commanded speed covers in kChunkSeconds -- and the next one only after the previous request
// finished, i.e. after the axes reported arrival. Never a target far ahead: releasing the
// input ends jogging within one short move, which ends by itself (there is no stop).
class TargetJogger : public QObject
{
    Q_OBJECT
public:
    static constexpr double kChunkSeconds = 0.2;

    explicit TargetJogger(ControllerSession* session, QObject* parent = nullptr);

    // Steps/s per axis (0 or missing: that axis rests). Takes effect with the next target.
    void setVelocities(const AxisVelocities& stepsPerS);
    void release(); // no further targets; the one under way finishes by itself
    bool isActive() const { return !m_velocities.isEmpty(); }
    bool targetInFlight() const { return m_inFlight != 0; }
    static qint64 chunkSteps(double stepsPerS);

Q_SIGNALS:
    void refused(const QString& reason);

private:
    void sendNext();
    void onResult(const CommandResult& result);

    ControllerSession* m_session;
    AxisVelocities m_velocities;
    RequestId m_inFlight = 0;
};

} // namespace stepdeck
