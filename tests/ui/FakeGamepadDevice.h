#pragma once
// A scriptable gamepad for the jog tests: this machine has no input devices.
#include "gamepad/GamepadDevice.h"
#include <QVector>

namespace stepdeck::test {

class FakeGamepadDevice : public ui::GamepadDevice
{
    Q_OBJECT
public:
    explicit FakeGamepadDevice(QObject* parent = nullptr) : ui::GamepadDevice(parent) {}

    bool isConnected() const override { return m_connected; }
    QString name() const override { return QStringLiteral("Fake Pad"); }
    int axisCount() const override { return int(m_axes.size()); }
    int buttonCount() const override { return int(m_buttons.size()); }
    double axis(int index) const override { return m_axes.value(index); }
    bool button(int index) const override { return m_buttons.value(index); }

    void plug(bool connected)
    {
        m_connected = connected;
        if (!connected) {
            m_axes.fill(0.0);
            m_buttons.fill(false);
        }
        Q_EMIT connectedChanged(connected);
    }
    void moveAxis(int index, double value)
    {
        m_axes[index] = value;
        Q_EMIT axisChanged(index, value);
    }
    void press(int index, bool down)
    {
        m_buttons[index] = down;
        Q_EMIT buttonChanged(index, down);
    }

private:
    bool m_connected = false;
    QVector<double> m_axes = QVector<double>(6, 0.0);
    QVector<bool> m_buttons = QVector<bool>(16, false);
};

} // namespace stepdeck::test
