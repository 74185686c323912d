#pragma once
// A scriptable gamepad for the jog tests: this machine has no input devices.
// Like the SDL backend it is sampled periodically while plugged in (sampled() every
// kSampleMs); setSampling(false) freezes the device (a stalled driver or poll: samples stop
// while the stick and the dead-man button stay where they were).
#include "gamepad/GamepadDevice.h"
#include <QTimer>
#include <QVector>

namespace stepdeck::test {

// The gamepad's default dead-man button (SDL_CONTROLLER_BUTTON_LEFTSHOULDER) and the axis of the
// X slot (the left stick's horizontal), as the jog tests press and tilt them.
constexpr int kDeadman = 9;
constexpr int kLeftX = 0;

class FakeGamepadDevice : public ui::GamepadDevice
{
    Q_OBJECT
public:
    static constexpr int kSampleMs = 20;

    explicit FakeGamepadDevice(QObject* parent = nullptr) : ui::GamepadDevice(parent)
    {
        m_sampler.setInterval(kSampleMs);
        connect(&m_sampler, &QTimer::timeout, this, [this] {
            ++m_samples;
            Q_EMIT sampled();
        });
    }

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
        updateSampler();
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
    void setSampling(bool on)
    {
        m_sampling = on;
        updateSampler();
    }
    int samples() const { return m_samples; }

private:
    void updateSampler()
    {
        if (m_connected && m_sampling)
            m_sampler.start();
        else
            m_sampler.stop();
    }

    bool m_connected = false;
    bool m_sampling = true;
    int m_samples = 0;
    QTimer m_sampler{this};
    QVector<double> m_axes = QVector<double>(6, 0.0);
    QVector<bool> m_buttons = QVector<bool>(16, false);
};

} // namespace stepdeck::test
