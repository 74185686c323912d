#pragma once
// Shared by the tests that build machines on simulators (tst_machine, tst_machinestop,
// tst_programrunner, tst_programcheckedruns): a machine axis in one line, and the setup a
// board wants before it moves, written and acknowledged.
#include "ModelBench.h"
#include "controller/ControllerSession.h"
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

// Writes the schema defaults of ModelInfo::setupBeforeMotion (E-LAB: tmInvSetup until the
// ramp is written) and waits until the session acknowledged the write; false if it did not.
inline bool writeSetupBeforeMotion(ControllerSession* session, int timeoutMs = 10000)
{
    QSignalSpy done(session, &ControllerSession::requestFinished);
    const RequestId id =
        session->writeParameters(setupBeforeMotionDefaults(*session->model()), false);
    return QTest::qWaitFor(
        [&] {
            return std::any_of(done.cbegin(), done.cend(), [id](const QList<QVariant>& args) {
                const auto r = args.at(0).value<CommandResult>();
                return r.id == id && r.ok();
            });
        },
        timeoutMs);
}

} // namespace stepdeck::test
