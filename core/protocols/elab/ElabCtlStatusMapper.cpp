#include "ElabCtlStatusMapper.h"
#include "ElabCtlParameters.h"
#include <QCoreApplication>

namespace stepdeck::elab {

namespace {
quint8 moveBit(Axis axis)
{
    return wireAxis(axis).moveBit;
}
quint8 jogBit(Axis axis)
{
    return wireAxis(axis).jogBit;
}
quint16 limitBit(Axis axis)
{
    return wireAxis(axis).limitSwitchBit;
}
quint16 referenceBit(Axis axis)
{
    return wireAxis(axis).referenceSwitchBit;
}
constexpr quint8 kMoveBits = axe::XMove | axe::YMove | axe::ZMove;
constexpr quint8 kJogBits = axe::XJog | axe::YJog | axe::ZJog;
constexpr quint16 kLimitBits = machine::LimSwX | machine::LimSwY | machine::LimSwZ;
} // namespace

const QList<Axis>& ElabCtlStatusMapper::axes()
{
    return boardAxes();
}

bool ElabCtlStatusMapper::axisMoving(quint8 axeState, Axis axis)
{
    return axeState & moveBit(axis);
}

bool ElabCtlStatusMapper::axisJogging(quint8 axeState, Axis axis)
{
    return axeState & jogBit(axis);
}

bool ElabCtlStatusMapper::anyMoveBit(quint8 axeState)
{
    return axeState & kMoveBits;
}
bool ElabCtlStatusMapper::anyJogBit(quint8 axeState)
{
    return axeState & kJogBits;
}

bool ElabCtlStatusMapper::limitSwitch(quint16 machineState, Axis axis)
{
    return machineState & limitBit(axis);
}

bool ElabCtlStatusMapper::referenceSwitch(quint16 machineState, Axis axis)
{
    return machineState & referenceBit(axis);
}

void ElabCtlStatusMapper::applyMachineState(MachineStatus& status, quint16 word, bool hostPanic)
{
    status.driveOn = word & machine::DriveOn;
    status.spindleOn = word & machine::SpindleOn;
    status.busy = word & machine::Busy;
    status.overTemperature = word & machine::OverTemp;
    status.setupIncomplete = word & machine::InvSetup;
    status.panic = (word & machine::PanicStop) || hostPanic;
    for (Axis a : axes()) {
        AxisStatus& axis = status.axes[a];
        axis.limitSwitch = limitSwitch(word, a);
        axis.referenceSwitch = referenceSwitch(word, a);
    }
    status.raw.insert(QStringLiteral("machineState"), int(word));
}

void ElabCtlStatusMapper::applyAxeState(MachineStatus& status, quint8 byte)
{
    for (Axis a : axes()) {
        AxisStatus& axis = status.axes[a];
        axis.moving = axisMoving(byte, a);
        axis.jogging = axisJogging(byte, a);
    }
    status.raw.insert(QStringLiteral("axeState"), int(byte));
}

void ElabCtlStatusMapper::applyTemperature(MachineStatus& status, quint8 celsius)
{
    status.temperatureCelsius = double(celsius);
}

QString ElabCtlStatusMapper::refusal(Rule rule, quint16 machineState, quint8 axeState)
{
    if (rule == Rule::Standstill) {
        // "Sind Positionier- oder Arbeits Kommandos beim Controller in Arbeit, so muss der Host
        // den Status des Controllers abfragen, bevor er weitere Kommandos absetzen kann"; during
        // a feed "keine weiteren Kommandos". Setup is what fixes tmInvSetup, so it is no reason.
        if (anyMoveBit(axeState) || anyJogBit(axeState) || (machineState & machine::Busy))
            return tr("refused: axes are moving (%1); setup and outputs are written only at "
                      "standstill")
                .arg(describeAxeState(axeState & (kMoveBits | kJogBits)));
        return {};
    }
    // "Allgemeine Hinweise" and the notes of every move section: a correct setup first, the
    // emergency stop released, standstill (RequestAxeState until idle) and, except for jog,
    // no active limit switch.
    if (machineState & machine::PanicStop)
        return tr("refused: the emergency stop (tmPanicStop) is active");
    if (machineState & machine::InvSetup)
        return tr("refused: setup incomplete (tmInvSetup): %1")
            .arg(ElabCtlParameters::setupIncompleteHint());
    switch (rule) {
    case Rule::Move:
        if ((machineState & kLimitBits) || (axeState & axe::LimSw))
            return tr("refused: a limit switch is active (%1); only jog may move the machine "
                      "off it")
                .arg(describeMachineState(machineState & kLimitBits));
        if (anyMoveBit(axeState) || anyJogBit(axeState) || (machineState & machine::Busy))
            return tr("refused: axes still moving (%1); wait until RequestAxeState reports "
                      "standstill")
                .arg(describeAxeState(axeState & (kMoveBits | kJogBits)));
        return {};
    case Rule::FirstJog:
        // Jog is the one mode allowed on an active limit switch (RequestAxeState, taLimSw).
        if (anyMoveBit(axeState))
            return tr("jog refused: axes still moving (%1); wait until they stand still")
                .arg(describeAxeState(axeState & kMoveBits));
        return {};
    case Rule::VelocityUpdate:
        if ((machineState & kLimitBits) || (axeState & axe::LimSw))
            return tr("refused: a limit switch is active (%1)")
                .arg(describeMachineState(machineState & kLimitBits));
        return {};
    case Rule::Standstill:
        return {};
    }
    return {};
}

} // namespace stepdeck::elab
