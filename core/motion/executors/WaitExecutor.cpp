#include "WaitExecutor.h"
#include "SwitchExecutor.h"
#include "machine/Machine.h"
#include <algorithm>

namespace stepdeck::motion {

namespace {
int milliseconds(double seconds)
{
    return int(std::clamp(seconds * 1000.0, 0.0, 2.0e9));
}
} // namespace

WaitExecutor::WaitExecutor(machine::Machine* machine, QObject* parent)
    : QObject(parent), m_machine(machine)
{
    m_dwell.setSingleShot(true);
    m_dwell.setTimerType(Qt::PreciseTimer);
    connect(&m_dwell, &QTimer::timeout, this,
            [this] { Q_EMIT finished(true, ErrorKind::None, {}); });
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        fail(ErrorKind::Timeout, tr("input %1 did not reach its level in time").arg(m_input));
    });
    connect(machine, &machine::Machine::requestFinished, this, &WaitExecutor::onRequestFinished);
    connect(machine, &machine::Machine::statusChanged, this, &WaitExecutor::checkInput);
}

void WaitExecutor::push(const MotionCommand& command)
{
    if (const auto* dwell = std::get_if<Dwell>(&command))
        m_dwell.start(milliseconds(dwell->seconds));
    else if (const auto* wait = std::get_if<WaitInput>(&command))
        startInput(*wait);
}

void WaitExecutor::cancel()
{
    m_dwell.stop();
    m_timeout.stop();
    m_input = 0;
    m_read = 0;
}

void WaitExecutor::startInput(const WaitInput& wait)
{
    const machine::MachineDescription& d = m_machine->description();
    QMap<QString, Capabilities> capabilities;
    for (const machine::MachineController& c : d.controllers)
        if (const ControllerSession* s = m_machine->session(c.id))
            capabilities.insert(c.id, s->capabilities());
    const std::optional<SwitchExecutor::Io> io =
        SwitchExecutor(d, capabilities, {}).input(wait.number);
    if (!io) {
        Q_EMIT finished(false, ErrorKind::Unsupported,
                        tr("the machine has no input %1").arg(wait.number));
        return;
    }
    m_input = wait.number;
    m_high = wait.high;
    m_controller = io->controller;
    m_number = io->number;
    m_read = m_machine->session(io->controller)->refreshStatus();
    m_timeout.start(milliseconds(wait.seconds));
}

void WaitExecutor::checkInput()
{
    if (m_input == 0 || m_read != 0)
        return;
    const MachineStatus& status = m_machine->session(m_controller)->status();
    if (!status.inputs || m_number > status.inputs->size() ||
        status.inputs->at(m_number - 1) != m_high)
        return;
    cancel();
    Q_EMIT finished(true, ErrorKind::None, {});
}

void WaitExecutor::onRequestFinished(const QString&, const CommandResult& result)
{
    if (result.id == 0 || result.id != m_read)
        return;
    if (!result.ok()) {
        fail(result.error, tr("input %1: %2").arg(m_input).arg(result.message));
        return;
    }
    m_read = 0;
    checkInput();
}

void WaitExecutor::fail(ErrorKind kind, const QString& message)
{
    cancel();
    Q_EMIT finished(false, kind, message);
}

} // namespace stepdeck::motion
