#pragma once
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include "motion/MotionCommand.h"
#include <QCoreApplication>
#include <QMap>
#include <optional>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::motion {

// The executor of the switch commands (issue 49 item 3, docs/architecture.md "One motion
// path"): SpindleOn, SpindleSpeed, SpindleOff, Coolant and Output on the machine's controllers.
// The one place that knows which controller switches the spindle, the coolant or output n, the
// value an S is sent as (the machine's spindle scale over the controller's spindle-speed
// parameter, as GRBL's $30) and whether the spindle reverses. The check asks accepts() of the
// command the lowering made of a block (ProgramLowering::switchCommand); the run asks it again
// with the machine as it is then and push()es: what the run would refuse here, the check named
// first, by construction. Pure but for push().
class SwitchExecutor
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::motion::SwitchExecutor)
public:
    SwitchExecutor(const machine::MachineDescription& description,
                   const QMap<QString, Capabilities>& capabilities,
                   const QMap<QString, ParameterSchema>& schemas);

    struct Refusal
    {
        ErrorKind kind = ErrorKind::Unsupported;
        // The word the refusal is about, for the check's column: "S", "P"; empty: the
        // command's own word (M3, M8, M64).
        QString word;
        QString text;
    };
    // nullopt: the machine takes it, or it is no switch command.
    std::optional<Refusal> accepts(const MotionCommand& command) const;
    // Seconds: a switch ends when its controller acknowledges it, which the estimate does not
    // count (as for the other commands, only motion and dwells take time).
    double estimate(const MotionCommand& command) const;
    // Sends an accepted switch command: its request's id, and *controller the controller's id;
    // 0 when it is none this machine can make (accepts() says why).
    RequestId push(const MotionCommand& command, machine::Machine& machine,
                   QString* controller) const;

    // The controller that switches the spindle (has = &Capabilities::spindle) or coolant
    // (&Capabilities::coolant): the first that has one, in the file's order; empty: none.
    QString switchController(bool Capabilities::*has) const;
    // The machine's outputs / inputs counted from 1 over the controllers in the file's order
    // (docs/programs.md "Inputs and outputs"), as the controller and its own number (1-based,
    // as MachineStatus and the model operation kSetOutput count). nullopt: no such one.
    struct Io
    {
        QString controller;
        int number = 0;
    };
    std::optional<Io> output(int n) const;
    std::optional<Io> input(int n) const;

    // The S the spindle runs at (rpm): at most maxRpm (GRBL's $30), where the machine has a
    // scale (issue 50: above it, it runs at maxRpm; the check notes it).
    static double spindleRpm(double s, std::optional<double> maxRpm);
    // M3 S as the value the spindle's controller is sent (docs/programs.md "Spindle speed",
    // issue 29). With the machine's spindle scale (MachineSpindle::maxRpm) S in rpm maps
    // linearly onto 0..the maximum of the controller's spindle-speed parameter
    // (Capabilities::spindleSpeedParameter), S / maxRpm x full scale; an S above 0 maps to at
    // least 1, since 0 switches the spindle off. Without a scale (or without such a parameter)
    // S is sent as written, as a whole number.
    static int spindleValue(const Capabilities& caps, const ParameterSchema& schema,
                            std::optional<double> maxRpm, double s);
    // Why M3 S would be refused: S above maxRpm where the machine refuses it (limits: Refuse;
    // with Clamp it runs at maxRpm), or spindleValue outside the schema range of the
    // spindle-speed parameter. Empty: the controller takes it. The default refuses, as the
    // window's spindle switch does with an S typed above maxRpm.
    static QString spindleSpeed(const Capabilities& caps, const ParameterSchema& schema,
                                std::optional<double> maxRpm, double s,
                                machine::LimitPolicy limits = machine::LimitPolicy::Refuse);
    // M4: why `controller` cannot turn its spindle in reverse (Capabilities::spindleReverse).
    // Empty: it can, or the spindle output drives a laser (MachineSpindle::laser), where M4 is
    // GRBL's dynamic power and runs as M3 (issue 50 item 5).
    static QString spindleReverse(const Capabilities& caps, const QString& controller,
                                  const machine::MachineSpindle& spindle);

    // The G-code word of a switch command, as a refusal names it ("M4", "S", "M65 P2").
    static QString wordOf(const MotionCommand& command);

private:
    std::optional<Refusal> acceptsSpindle(const MotionCommand& command) const;
    std::optional<Refusal> acceptsOutput(const Output& output) const;
    std::optional<Io> nthIo(int n, int Capabilities::*count) const;

    const machine::MachineDescription& m_d;
    QMap<QString, Capabilities> m_caps;
    QMap<QString, ParameterSchema> m_schemas;
};

} // namespace stepdeck::motion
