#pragma once
#include "model/Axis.h"
#include <QObject>

namespace stepdeck::ui {

// Anything that can request jog motion: the on-screen pad and sticks, the keyboard, a
// physical gamepad. A source reports speed fractions per axis (-1..1, already shaped by its
// dead zone and response curve); an empty map or all zeros means "released".
// The JogController turns fractions into velocities and keeps the core's jog lease alive.
class JogInputSource : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    virtual QString sourceName() const = 0;

Q_SIGNALS:
    void deflectionChanged(const stepdeck::AxisVelocities& fractions);
};

} // namespace stepdeck::ui
