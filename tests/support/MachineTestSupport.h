#pragma once
// Shared by the tests that build machines on simulators (tst_machine, tst_machinestop,
// tst_programrunner, tst_programcheckedruns): a machine axis in one line, and the setup a
// board wants before it moves, written and acknowledged.
#include "ModelBench.h"
#include "controller/ControllerSession.h"
#include "machine/Machine.h"
#include "machine/MachineDescription.h"
#include <QSignalSpy>
#include <QTest>
#include <algorithm>

namespace stepdeck::test {

inline machine::MachineAxis machineAxis(const QString& name, const QString& controller, Axis on,
                                        machine::AxisUnit unit, double stepsPerUnit)
{
    machine::MachineAxis a;
    a.name = name;
    a.controller = controller;
    a.axis = on;
    a.unit = unit;
    a.stepsPerUnit = stepsPerUnit;
    return a;
}

// Writes `set` and waits until the session acknowledged the write; false if it did not.
inline bool writeParametersAndWait(ControllerSession* session, const ParameterSet& set,
                                   int timeoutMs = 10000)
{
    QSignalSpy done(session, &ControllerSession::requestFinished);
    const RequestId id = session->writeParameters(set, false);
    return QTest::qWaitFor(
        [&] {
            return std::any_of(done.cbegin(), done.cend(), [id](const QList<QVariant>& args) {
                const auto r = args.at(0).value<CommandResult>();
                return r.id == id && r.ok();
            });
        },
        timeoutMs);
}

// Writes the schema defaults of ModelInfo::setupBeforeMotion (E-LAB: tmInvSetup until the
// ramp is written) and waits until the session acknowledged the write; false if it did not.
inline bool writeSetupBeforeMotion(ControllerSession* session, int timeoutMs = 10000)
{
    return writeParametersAndWait(session, setupBeforeMotionDefaults(*session->model()), timeoutMs);
}

// E-LAB programs with feeds up to 2000 steps/s: the board's feed mode runs below the start
// speed (manual), and a stream of several axes goes at the slowest of the three feed speeds
// while a G1 writes only the moving axes' (the contouring issue changes that): every axis gets
// start speed 2000 and feed speed 1000.
inline bool raiseElabFeedLimits(ControllerSession* table)
{
    ParameterValue start, feed;
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        start.perAxis.insert(a, 2000);
        feed.perAxis.insert(a, 1000);
    }
    return writeParametersAndWait(
        table, {{QStringLiteral("start-speed"), start}, {QStringLiteral("feed-speed"), feed}});
}

// What a program run on a table of one E-LAB or EMIS controller wants first (tst_camprograms,
// tst_ngcrun). E-LAB: the ramp setup the board needs, start speeds that allow feeds up to
// 2000 steps/s (feed mode runs below the start speed, manual). EMIS: the work speed of
// positioning moves, as a technician's setup writes it (the fast speed a program's G0 runs at
// and G1's F replaces). Then a reference run of every axis.
inline bool prepareTableForPrograms(machine::Machine* machine, const QString& controller)
{
    ControllerSession* table = machine->session(controller);
    if (table->model()->id == QLatin1String("elab")) {
        if (!writeSetupBeforeMotion(table) || !raiseElabFeedLimits(table))
            return false;
    } else {
        ParameterValue work;
        for (Axis a : {Axis::X, Axis::Y, Axis::Z})
            work.perAxis.insert(a, 4000);
        if (!writeParametersAndWait(table, {{QStringLiteral("work-speed"), work}}))
            return false;
    }
    QSignalSpy referenced(machine, &machine::Machine::referenceFinished);
    QString refusal;
    return machine->reference({}, &refusal) != 0 && referenced.wait(60000) &&
           referenced.first().at(1).toBool();
}

} // namespace stepdeck::test
