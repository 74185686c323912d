#include "SoakModels.h"
#include "protocols/elab/ElabCodec.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/emis/EmisSimulator.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "protocols/laser/LaserCodec.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include <QElapsedTimer>
#include <QThread>

namespace stepdeck::bench {

namespace {
constexpr qint64 kFar = 1'000'000'000; // switches out of reach of any soak run

// The probes every model's simulator answers the same way (isMoving, acceptedMoves).
template <typename Sim> std::function<QList<Axis>(Simulator*)> movingAxesOf(QList<Axis> axes)
{
    return [axes](Simulator* s) {
        auto* sim = qobject_cast<Sim*>(s);
        QList<Axis> out;
        for (Axis a : axes) {
            if (sim->isMoving(a))
                out << a;
        }
        return out;
    };
}

template <typename Sim> QList<DeviceMove> acceptedMovesOf(Simulator* s)
{
    QList<DeviceMove> out;
    for (const auto& move : qobject_cast<Sim*>(s)->acceptedMoves())
        out.append({move.axis, move.steps});
    return out;
}

ParameterValue perAxis(qint64 value, const QList<Axis>& axes)
{
    ParameterValue v;
    for (Axis a : axes)
        v.perAxis.insert(a, value);
    return v;
}

SoakModel elabModel()
{
    const QList<Axis> xyz{Axis::X, Axis::Y, Axis::Z};
    SoakModel m;
    m.id = QStringLiteral("elab");
    m.setup = {{QStringLiteral("start-speed"), perAxis(500, xyz)},
               {QStringLiteral("max-speed"), perAxis(8000, xyz)},
               {QStringLiteral("acceleration"), perAxis(20000, xyz)},
               {QStringLiteral("feed-speed"), perAxis(200, xyz)}};
    m.prepare = [xyz](Simulator* s) {
        auto* sim = qobject_cast<elab::ElabSimulator*>(s);
        for (Axis a : xyz)
            sim->setLimitPositions(a, -kFar, kFar);
    };
    m.movingAxes = movingAxesOf<elab::ElabSimulator>(xyz);
    m.moves = acceptedMovesOf<elab::ElabSimulator>;
    // ForceStopMove, as the host would send it; the ACK goes nowhere between sessions.
    m.halt = [](Simulator* s) { s->receive(elab::encode::stopMove()); };
    return m;
}

SoakModel nanotecModel()
{
    const QMap<int, Axis> axisOf{{1, Axis::X}, {2, Axis::Y}, {3, Axis::Z}}; // the CLI's default
    SoakModel m;
    m.id = QStringLiteral("nanotec");
    m.simulator.addresses = axisOf.keys();
    m.readable = {QStringLiteral("phase-current"), QStringLiteral("max-frequency")};
    m.recovery = {QStringLiteral("reset-position-error")};
    m.setup = {
        {QStringLiteral("max-frequency"), perAxis(8000, axisOf.values())},
        {QStringLiteral("ramp"), perAxis(20, axisOf.values())}}; // ramp 20: ~660 Hz/ms (6.11)
    m.prepare = [](Simulator* s) {
        for (nanotec::NanotecDrive* d : qobject_cast<nanotec::NanotecSimulator*>(s)->drives())
            d->setSwitches(-kFar, kFar);
    };
    m.movingAxes = [axisOf](Simulator* s) {
        QList<Axis> out;
        for (nanotec::NanotecDrive* d : qobject_cast<nanotec::NanotecSimulator*>(s)->drives()) {
            if (d->isActive() && axisOf.contains(d->address()))
                out << axisOf.value(d->address());
        }
        return out;
    };
    m.moves = [axisOf](Simulator* s) {
        QList<DeviceMove> out;
        for (const auto& move : qobject_cast<nanotec::NanotecSimulator*>(s)->startedMoves())
            out.append({axisOf.value(move.address, Axis::U), move.steps});
        return out;
    };
    m.halt = [](Simulator* s) { s->receive("#*S\r"); }; // 6.2: every drive stops
    return m;
}

SoakModel emisModel()
{
    const QList<Axis> xyzu = allAxes();
    SoakModel m;
    m.id = QStringLiteral("emis");
    m.setup = {{QStringLiteral("start-speed"), perAxis(500, xyzu)},
               {QStringLiteral("work-speed"), perAxis(4000, xyzu)},
               {QStringLiteral("ramp"), ParameterValue{QVariant(qint64(50)), {}}}};
    m.prepare = [xyzu](Simulator* s) {
        auto* sim = qobject_cast<emis::EmisSimulator*>(s);
        for (Axis a : xyzu)
            sim->setSwitchPosition(a, std::nullopt); // no reference switch within reach
    };
    m.movingAxes = movingAxesOf<emis::EmisSimulator>(xyzu);
    m.moves = acceptedMovesOf<emis::EmisSimulator>;
    // The SMC-IC4 has no stop command (chapter 9): the machine's emergency stop.
    m.halt = [](Simulator* s) { qobject_cast<emis::EmisSimulator*>(s)->emergencyStop(); };
    m.stopCommand = false;
    return m;
}

SoakModel laserModel()
{
    const QList<Axis> xyz{Axis::X, Axis::Y, Axis::Z};
    SoakModel m;
    m.id = QStringLiteral("laser-axis");
    // Every axis homed and standing mid-range (the protocol's positions are 0..99999), so the
    // random walk of the soak's moves stays inside; then 2000 units/s, no ramps.
    m.prepare = [xyz](Simulator* s) {
        auto* sim = qobject_cast<laser::LaserAxisSimulator*>(s);
        const bool silent = s->faults().silent;
        s->faults().silent = true; // the status frames of the set-up reach nobody
        sim->setSpeed(1e9);
        for (Axis a : xyz) {
            sim->config(a).endSwitch = kFar;
            sim->receive(laser::encodeMove(a, laser::kMaxPosition / 2));
        }
        QElapsedTimer clock;
        clock.start();
        while (!sim->standingStill() && clock.elapsed() < 2000)
            QThread::msleep(1);
        sim->clearAcceptedMoves();
        sim->setSpeed(2000);
        s->faults().silent = silent;
    };
    m.movingAxes = movingAxesOf<laser::LaserAxisSimulator>(xyz);
    m.moves = acceptedMovesOf<laser::LaserAxisSimulator>;
    // The protocol has no stop command: the machine's emergency stop.
    m.halt = [](Simulator* s) { qobject_cast<laser::LaserAxisSimulator*>(s)->emergencyStop(); };
    m.stopCommand = false;
    m.anchor = [xyz](Simulator* s) {
        auto* sim = qobject_cast<laser::LaserAxisSimulator*>(s);
        AxisVector out;
        for (Axis a : xyz)
            out.insert(a, sim->position(a));
        return out;
    };
    return m;
}
} // namespace

const QList<SoakModel>& soakModels()
{
    static const QList<SoakModel> models{elabModel(), nanotecModel(), emisModel(), laserModel()};
    return models;
}

const SoakModel* findSoakModel(const QString& id)
{
    for (const SoakModel& m : soakModels()) {
        if (m.id == id)
            return &m;
    }
    return nullptr;
}

} // namespace stepdeck::bench
