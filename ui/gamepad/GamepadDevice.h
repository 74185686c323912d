#pragma once
#include <QObject>

namespace stepdeck::ui {

// A physical joystick or gamepad as raw axes (-1..1, as the device reports them) and
// buttons, with hot-plug. The SDL2 backend is SdlGamepadDevice; tests use a fake.
// sampled() follows every fresh read of the device (SDL: each poll, every 10 ms), whether or
// not anything changed: a held stick only proves it is still held by these samples.
class GamepadDevice : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    virtual bool isConnected() const = 0;
    virtual QString name() const = 0;
    virtual int axisCount() const = 0;
    virtual int buttonCount() const = 0;
    virtual double axis(int index) const = 0;
    virtual bool button(int index) const = 0;
    // Why there is no device support at all (backend missing or failed), else empty.
    virtual QString backendError() const { return {}; }

Q_SIGNALS:
    void connectedChanged(bool connected);
    void axisChanged(int index, double value);
    void buttonChanged(int index, bool pressed);
    void sampled(); // the device was read just now; axis() and button() are current
};

// The platform's device: SDL2 when built with it, otherwise a device that never connects and
// says why.
GamepadDevice* createSystemGamepadDevice(QObject* parent);

} // namespace stepdeck::ui
