#pragma once
#include "jog/JogSlot.h"
#include <QObject>

namespace stepdeck::ui {

// Anything that can request jog motion: the on-screen pad and sticks, the keyboard, a
// physical gamepad. A source reports speed fractions per jog slot (-1..1, already shaped by its
// dead zone and response curve); an empty map or all zeros means "released".
//
// Proof of holding (issue 7, rule 3): the JogController renews the core's jog lease only for
// what a source can prove is still held at that moment, never because a timer fired. At every
// renewal it calls heldDeflection(), and each source answers with zeros for everything it
// cannot prove now:
// - keyboard: a key counts as held only while its auto-repeat keeps arriving (the key press
//   itself counts until the first repeat is due, see KeyboardJog), so a lost key-up ends by
//   itself;
// - pointer: the drag counts only while QGuiApplication::mouseButtons() still shows the
//   button down, read at each renewal, so a lost mouse release ends by itself;
// - gamepad: only a fresh device sample with the dead-man button held.
//
// Latching (rule 4): latch() is called on STOP, PANIC and focus loss. Whatever is deflected
// at that moment contributes zero until it has returned to neutral or been released, so the
// same key, pad or stick cannot restart motion by itself.
class JogInputSource : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    virtual QString sourceName() const = 0;
    // The deflection this source proves right now (zeros for anything unproven or latched).
    virtual SlotVelocities heldDeflection() = 0;
    // STOP, PANIC, focus loss: no motion from what is held now until it is released.
    virtual void latch() = 0;

Q_SIGNALS:
    // The deflection or its proof changed: the controller reads heldDeflection() again.
    void changed();
};

} // namespace stepdeck::ui
