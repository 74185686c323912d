// Soft limits on every model, through the generic Controller interface against each model's
// simulator (issue 11). Each case asserts what the DEVICE saw: a jog pushed into the limit
// ends with the simulated axis standing inside the range (E-LAB: the host ramp brakes in
// time; Nanotec: the drive's own ramp and the bus latency are allowed for; EMIS and laser
// axes: no jog chunk or jog target crosses the limit), a move, velocity move or target beyond
// the limit is refused with the reason and not one new frame reaches the device, a move
// inside goes, and an unreferenced axis is not held by limits.
#include "ModelBench.h"
#include "TestSupport.h"
#include "controller/Controller.h"
#include "protocols/Registry.h"
#include "protocols/elab/ElabSimulator.h"
#include "protocols/laser/LaserAxisSimulator.h"
#include "protocols/nanotec/NanotecDrive.h"
#include "protocols/nanotec/NanotecSimulator.h"
#include "sim/Simulator.h"
#include "transport/LoopbackTransport.h"
#include <QDeadlineTimer>
#include <QSet>
#include <QtTest>
#include <memory>

using namespace stepdeck;

namespace {
constexpr qint64 kTravel = 2000; // the limit lies this far from the referenced position
// How far a host's jog estimate may drift from the device: the jog's 1000 steps/s times 25 ms
// of varying serial latency on a loaded machine (CI has seen 1 to 3 steps).
constexpr qint64 kEstimateSlack = 25;

struct Bench : test::ModelBench
{
    explicit Bench(const ModelInfo* model) : ModelBench(model, 500), id(model->id)
    {
        refusals = std::make_unique<QSignalSpy>(ctl.get(), &Controller::jogRefused);
    }

    CommandResult run(const std::function<void(RequestId)>& call, int timeoutMs = 10000)
    {
        return ModelBench::run(call, timeoutMs);
    }
    bool write(const QStringList& assignments)
    {
        ParameterSet set;
        for (const QString& a : assignments) {
            QString name, error;
            ParameterValue value;
            if (!info->schema.parseAssignment(a, info->capabilities.axes, &name, &value, &error)) {
                qWarning() << a << error;
                return false;
            }
            set.insert(name, value);
        }
        const CommandResult r = run([&](RequestId rid) { ctl->writeParameters(rid, set, false); });
        if (!r.ok())
            qWarning() << "write:" << r.message;
        return r.ok();
    }
    // Connected, set up to move, X referenced.
    bool prepareAndReference()
    {
        if (!run([this](RequestId rid) { ctl->openLink(rid); }).ok())
            return false;
        int direction = 1;
        if (id == QLatin1String("elab")) {
            if (!write({"start-speed=100", "max-speed=5000", "acceleration=4000", "feed-speed=50"}))
                return false;
            direction = -1;
            // The reference switch close by: the reference run is not what is tested here.
            static_cast<elab::ElabSimulator*>(sim.get())->setReferencePosition(Axis::X, -500, 10);
        } else if (id == QLatin1String("emis")) {
            if (!write({"ramp=20", "start-speed=500", "work-speed=4000", "reference-speed=4000"}))
                return false;
        } else if (id == QLatin1String("nanotec")) {
            static_cast<nanotec::NanotecSimulator*>(sim.get())->drive(1)->setSwitches(-250, 1e6);
            direction = -1;
        }
        const CommandResult home = run([&](RequestId rid) {
            ctl->reference(rid, {{Axis::X, direction}});
        });
        if (!home.ok()) {
            qWarning() << "reference:" << home.message;
            return false;
        }
        QDeadlineTimer deadline(10000);
        while (!(ctl->status().axes.value(Axis::X).referenced && sim->standingStill()) &&
               !deadline.hasExpired())
            results->wait(20);
        return ctl->status().axes.value(Axis::X).referenced;
    }
    qint64 simX() { return sim->position(Axis::X); } // the device's own count
    qint64 hostX() const { return ctl->status().axes.value(Axis::X).position; }
    bool saidSoftLimit() const
    {
        for (const QList<QVariant>& args : *refusals) {
            if (args.at(0).toString().contains(QLatin1String("soft limit")))
                return true;
        }
        return false;
    }

    QString id;
    std::unique_ptr<QSignalSpy> refusals;
};
} // namespace

class TestSoftLimitsModels : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void limits_holdAtTheDevice_data();
    void limits_holdAtTheDevice();

private:
    // Jogs X towards +; returns the highest device position seen (machine steps).
    qint64 jogIntoTheLimit(Bench& b, qint64 offset);
};

void TestSoftLimitsModels::limits_holdAtTheDevice_data()
{
    QTest::addColumn<QString>("model");
    for (const ModelInfo& m : models())
        QTest::newRow(qPrintable(m.id)) << m.id;
}

qint64 TestSoftLimitsModels::jogIntoTheLimit(Bench& b, qint64 offset)
{
    qint64 highest = std::numeric_limits<qint64>::min();
    QDeadlineTimer deadline(20000);
    if (b.info->capabilities.jogByTargets) {
        // Short targets one after the other, as the GUI's TargetJogger sends them.
        for (;;) {
            const CommandResult r = b.run([&](RequestId rid) {
                b.ctl->jogStep(rid, {{Axis::X, 300}});
            });
            highest = qMax(highest, b.simX() - offset);
            if (!r.ok()) {
                if (!r.message.contains(QLatin1String("soft limit")))
                    qWarning() << "jog step:" << r.message;
                return highest;
            }
            if (deadline.hasExpired())
                return highest;
        }
    }
    // A held input: the lease renewed every 20 ms, until the device stands still after the
    // soft limit was named, and 300 ms more of pushing.
    QElapsedTimer pushedAfter;
    while (!deadline.hasExpired()) {
        b.ctl->setJogVelocity({{Axis::X, 1000}});
        b.results->wait(20);
        highest = qMax(highest, b.simX() - offset);
        if (b.saidSoftLimit() && b.sim->standingStill() && !pushedAfter.isValid())
            pushedAfter.start();
        if (pushedAfter.isValid() && pushedAfter.elapsed() > 300)
            break;
    }
    b.ctl->endJog();
    return highest;
}

void TestSoftLimitsModels::limits_holdAtTheDevice()
{
    QFETCH(QString, model);
    Bench b(findModel(model));
    QVERIFY(b.prepareAndReference());
    const qint64 home = b.hostX();
    const qint64 offset = b.simX() - home; // device counter vs. machine steps
    SoftLimits limits;
    limits.set(Axis::X, AxisSoftLimit{true, true, home - 100000, home + kTravel});
    limits.set(Axis::Y, AxisSoftLimit{true, true, -10, 10}); // Y is not referenced
    b.ctl->setSoftLimits(limits);
    const qint64 max = home + kTravel;

    // Jog pushed into the limit: the device never passes it and ends standing inside.
    const qint64 highest = jogIntoTheLimit(b, offset);
    QVERIFY2(b.saidSoftLimit() || b.info->capabilities.jogByTargets,
             "the jog was not stopped for the soft limit");
    QTRY_VERIFY_WITH_TIMEOUT(b.sim->standingStill(), 5000);
    const qint64 stopped = b.simX() - offset;
    QVERIFY2(
        highest <= max && stopped <= max,
        qPrintable(
            QStringLiteral("highest %1, stopped %2, limit %3").arg(highest).arg(stopped).arg(max)));
    QVERIFY2(stopped > home + kTravel / 2, qPrintable(QString::number(stopped - home)));
    if (model == QLatin1String("laser-axis")) {
        // Every target the axis received lies inside.
        for (const laser::CommandFrame& f :
             static_cast<laser::LaserAxisSimulator*>(b.sim.get())->receivedCommands()) {
            if (f.command == laser::Command::Move && f.axis == Axis::X)
                QVERIFY2(f.position - offset <= max, qPrintable(QString::number(f.position)));
        }
    }

    // Beyond the limit: refused with the reason, and not one new frame reaches the device.
    const QList<QByteArray> before = b.sim->receivedFrames();
    const QSet<QByteArray> seen(before.cbegin(), before.cend());
    const QList<std::function<void(RequestId)>> beyond{
        [&](RequestId rid) {
            b.ctl->guardedMoveRelative(rid, {{Axis::X, 1000}});
        },
        [&](RequestId rid) {
            b.ctl->guardedMoveAbsolute(rid, {{Axis::X, max + 1}});
        },
        [&](RequestId rid) {
            b.ctl->guardedFeed(rid, {{Axis::X, 1000}});
        },
        [&](RequestId rid) {
            b.ctl->guardedVelocityMove(rid, {{Axis::X, 500}});
        },
    };
    for (const auto& call : beyond) {
        const CommandResult r = b.run(call);
        QCOMPARE(r.error, ErrorKind::Refused);
        QVERIFY2(r.message.contains(QLatin1String("soft limit")), qPrintable(r.message));
    }
    const QList<QByteArray> after = b.sim->receivedFrames();
    for (qsizetype i = before.size(); i < after.size(); ++i)
        QVERIFY2(seen.contains(after.at(i)), after.at(i).constData());
    QCOMPARE(b.simX() - offset, stopped);

    // Inside: it goes. The move itself is exact: the device travels target - host position.
    // Where the host's position comes from a jog on a model without read-back (E-LAB: the host
    // integrates its commanded rates on its clock, the board applies them when the bytes
    // arrive), it is marked estimated and may be a few steps off the device's; else exact.
    const AxisStatus hostAxis = b.ctl->status().axes.value(Axis::X);
    const qint64 deviceBefore = b.simX();
    const CommandResult inside = b.run([&](RequestId rid) {
        b.ctl->guardedMoveAbsolute(rid, {{Axis::X, home + 500}});
    });
    QVERIFY2(inside.ok(), qPrintable(inside.message));
    QTRY_COMPARE_WITH_TIMEOUT(b.simX(), deviceBefore + (home + 500 - hostAxis.position), 10000);
    const qint64 estimateError = b.simX() - offset - (home + 500);
    if (hostAxis.positionEstimated) {
        QVERIFY(!b.info->capabilities.positionReadback);
        QVERIFY(b.ctl->status().axes.value(Axis::X).positionEstimated); // still marked
        QVERIFY2(qAbs(estimateError) <= kEstimateSlack, qPrintable(QString::number(estimateError)));
    } else {
        QCOMPARE(estimateError, qint64(0));
    }

    // Not referenced: limits do not apply (whatever else may refuse the move).
    const CommandResult y = b.run([&](RequestId rid) {
        b.ctl->guardedMoveRelative(rid, {{Axis::Y, 100}});
    });
    QVERIFY2(!y.message.contains(QLatin1String("soft limit")), qPrintable(y.message));
}

QTEST_MAIN(TestSoftLimitsModels)
#include "tst_softlimitsmodels.moc"
