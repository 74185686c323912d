#pragma once
// The rig of the ProgramRunner tests (tst_programrunner, tst_programrunnermotion): a machine
// of an E-LAB table (X, Y in mm) and a Nanotec rotary axis (A in degrees), each simulator on a
// real pseudo-terminal, the runner on it, and what the devices received and where they stand.
#include "MachineTestSupport.h"
#include "PtyDevice.h"
#include "machine/Machine.h"
#include "program/ProgramParser.h"
#include "program/ProgramRunner.h"
#include "protocols/elab/ElabSimulator.h"
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <memory>

namespace stepdeck::program::runnertest {

using namespace stepdeck::machine;

using Device = test::PtyDevice;

inline QList<qint64> acceptedSteps(Device& d, Axis axis)
{
    return d.probe([&] {
        QList<qint64> steps;
        for (const SimulatedMove& m : d.sim()->acceptedMoves())
            if (m.axis == axis)
                steps << m.steps;
        return steps;
    });
}

inline int acceptedCount(Device& d)
{
    return d.probe([&] { return int(d.sim()->acceptedMoves().size()); });
}

inline bool still(Device& d)
{
    return d.probe([&] { return d.sim()->standingStill(); });
}

inline bool moving(Device& d)
{
    return d.probe([&] { return !d.sim()->standingStill(); });
}

// The index of the first frame the device received that contains `part` after `from`; -1: none.
inline int frameIndex(Device& d, const QByteArray& part, int from = 0)
{
    const QList<QByteArray> frames = d.frames();
    for (int i = from; i < frames.size(); ++i)
        if (frames.at(i).contains(part))
            return i;
    return -1;
}

// The tests' base: a fresh rig per test function (setUpRig in init(), tearDownRig in cleanup()).
class ProgramRunnerFixture : public QObject
{
protected:
    void setUpRig();
    void tearDownRig();
    MachineDescription description() const;
    // The same devices as a machine of another description (a spindle scale).
    void recreateMachine(const MachineDescription& d);
    // The board moves only after its ramp setup was written (ModelInfo::setupBeforeMotion).
    void writeElabSetup();
    bool run(const QByteArray& text, int fromLine = 1, bool stepOnly = false);
    quint32 boardRpm() const; // the E-LAB simulator's spindle value (SetSpindleRPM)

    std::unique_ptr<Device> m_elab;
    std::unique_ptr<Device> m_nanotec;
    std::unique_ptr<Machine> m_machine;
    std::unique_ptr<ProgramRunner> m_runner;
};

inline MachineDescription ProgramRunnerFixture::description() const
{
    MachineDescription d;
    d.name = QStringLiteral("Table with rotary axis");
    d.controllers = {{"table", "elab", m_elab->path(), {}, {}, {}, {}, {}},
                     {"rotary", "nanotec", m_nanotec->path(), {{Axis::X, 1}}, {}, {}, {}, {}}};
    d.axes = {test::machineAxis("X", "table", Axis::X, AxisUnit::Millimetre, 400),
              test::machineAxis("Y", "table", Axis::Y, AxisUnit::Millimetre, 400),
              test::machineAxis("A", "rotary", Axis::X, AxisUnit::Degree, 100)};
    return d;
}

inline void ProgramRunnerFixture::setUpRig()
{
    m_elab = std::make_unique<Device>("elab");
    m_nanotec = std::make_unique<Device>("nanotec");
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(description(), &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    writeElabSetup();
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
}

inline void ProgramRunnerFixture::recreateMachine(const MachineDescription& d)
{
    m_runner.reset();
    m_machine.reset();
    m_machine = std::make_unique<Machine>();
    QString error;
    QVERIFY2(m_machine->create(d, &error), qPrintable(error));
    m_machine->open();
    QTRY_COMPARE_WITH_TIMEOUT(m_machine->state(), MachineState::Idle, 10000);
    writeElabSetup();
    m_runner = std::make_unique<ProgramRunner>(m_machine.get());
}

inline void ProgramRunnerFixture::tearDownRig()
{
    m_runner.reset();
    m_machine.reset();
    m_elab.reset();
    m_nanotec.reset();
}

inline void ProgramRunnerFixture::writeElabSetup()
{
    QVERIFY(test::writeSetupBeforeMotion(m_machine->session("table")));
}

inline bool ProgramRunnerFixture::run(const QByteArray& text, int fromLine, bool stepOnly)
{
    QList<ProgramError> errors;
    QStringList axes; // the machine's: X, Y, A, and Z where a test adds it
    for (const MachineAxis& a : m_machine->description().axes)
        axes << a.name;
    const std::optional<Program> program = ProgramParser::parse(text, axes, &errors);
    if (!program) {
        qWarning() << "parse:" << (errors.isEmpty() ? QString() : errors.first().text());
        return false;
    }
    if (!m_runner->start(*program, fromLine, &errors, stepOnly)) {
        for (const ProgramError& e : std::as_const(errors))
            qWarning() << "check:" << e.text();
        return false;
    }
    return true;
}

inline quint32 ProgramRunnerFixture::boardRpm() const
{
    return m_elab->probe(
        [&] { return static_cast<elab::ElabSimulator*>(m_elab->sim())->spindleRpm(); });
}

} // namespace stepdeck::program::runnertest

#define WAIT_ENDED() QTRY_VERIFY_WITH_TIMEOUT(isEnded(m_runner->state()), 60000)
#define VERIFY_STATE(expected)                                                                     \
    QVERIFY2(m_runner->state() == (expected), qPrintable(m_runner->endMessage()))
