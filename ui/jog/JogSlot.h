#pragma once
#include <QList>
#include <QMap>
#include <QMetaType>
#include <QString>

namespace stepdeck::ui {

// A place of the window's jog inputs (issue 32, step 1): the pad's two directions, the Z stick
// and the other stick. The pad, the sticks, the keyboard and a gamepad speak of these slots;
// JogAxisMap says which machine axis each one moves. A slot is no controller axis: a machine
// of six axes has four slots, and the other stick picks its axis.
enum class JogSlot : quint8 { PadHorizontal, PadVertical, ZStick, OtherStick };

// Per slot a speed fraction (-1..1, from a source) or a rate (unit/s of the slot's axis).
using SlotVelocities = QMap<JogSlot, double>;

const QList<JogSlot>& allJogSlots(); // in the order above
// The slot's settings key: "X", "Y", "Z", "U", as the keys were written before slots had a
// type of their own (gamepad bindings stay where they were saved).
QString jogSlotKey(JogSlot slot);

} // namespace stepdeck::ui

Q_DECLARE_METATYPE(stepdeck::ui::SlotVelocities)
