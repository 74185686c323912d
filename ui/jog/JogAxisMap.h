#pragma once
#include "jog/JogSlot.h"
#include "model/Axis.h"
#include "model/MachineStatus.h"
#include <QMap>
#include <QObject>

namespace stepdeck::machine {
struct MachineAxis;
}

namespace stepdeck::ui {

class MachineContext;

// Which axis each jog slot moves, and how fast it may (issue 19). The jog inputs (the pad,
// the sticks, the keyboard, a gamepad) always speak of four slots (JogSlot, issue 32): the
// pad's two directions, the Z stick and the other stick. Every slot is one of the machine's
// named axes (every connection is a machine, issue 28 item 0), on whichever controller drives
// it, and its rates are in that axis' unit/s: the pad its first two axes (X and Y when it has
// them), the Z stick Z, the other stick the axis the operator picks among the rest
// (otherStickChoices()), so every axis of a six-axis machine can be reached.
class JogAxisMap : public QObject
{
    Q_OBJECT
public:
    explicit JogAxisMap(MachineContext* context, QObject* parent = nullptr);

    bool isMachine() const; // false only while no model is chosen
    // Some axis it jogs is on a controller without a jog command (short targets instead).
    bool jogsByTargets() const;
    // The slots that move something (none without a machine).
    QList<JogSlot> jogSlots() const;
    const machine::MachineAxis* machineAxis(JogSlot slot) const; // null without a machine
    QString label(JogSlot slot) const; // what the slot moves: "A", or the controller's "U"

    // The machine axes the other stick can take (not on the pad or the Z stick).
    QStringList otherStickChoices() const;
    QString otherStickAxis() const { return m_slots.value(JogSlot::OtherStick); }
    void setOtherStickAxis(const QString& name);

    // Machine: the operator's max jog speed of the slot's axis in unit/s (persisted per
    // machine axis name), within ceiling(): the file's maxJogSpeed, or else the controller's
    // jog maximum in the axis' unit.
    double maxSpeed(JogSlot slot) const;
    void setMaxSpeed(JogSlot slot, double unitsPerSecond);
    double ceiling(JogSlot slot) const;
    // Slot rates (unit/s) as the machine axes' rates for Machine::jog.
    QMap<QString, double> machineRates(const SlotVelocities& slotRates) const;
    // The status of what the slot moves, its commanded velocity in the slot's rate unit.
    AxisStatus slotStatus(JogSlot slot, double* velocity) const;

public Q_SLOTS:
    void rebuild(); // the machine was opened or closed

Q_SIGNALS:
    void changed(); // the slots now move other axes: jogging was released

private:
    double ceilingOf(const machine::MachineAxis& axis) const;
    QString settingsKey(const QString& axisName) const;

    MachineContext* m_context;
    QMap<JogSlot, QString> m_slots; // machine only: slot -> machine axis name
    QMap<QString, double> m_maxSpeed;
};

// A machine axis' rate unit for the screen: "mm/s", "deg/s", "steps/s" (translated).
QString rateUnitName(const machine::MachineAxis& axis);
// A machine axis' commanded velocity in unit/s (its controller's status, inversion applied).
double commandedUnitsPerSecond(MachineContext* context, const machine::MachineAxis& axis,
                               AxisStatus* status = nullptr);

} // namespace stepdeck::ui
