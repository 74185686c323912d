#pragma once
#include "gamepad/GamepadDevice.h"
#include <QTimer>
#include <QVector>

#ifdef STEPDECK_HAVE_SDL2
namespace stepdeck::ui {

// SDL2's game-controller API (joystick API for devices SDL has no mapping for). SDL runs
// without a window here, so events are polled from a timer and background events allowed:
// every 10 ms while a device is open, a few times a second while none is (hot-plug).
// The first device plugged in is used; unplugging it reports disconnected at once.
class SdlGamepadDevice : public GamepadDevice
{
    Q_OBJECT
public:
    explicit SdlGamepadDevice(QObject* parent = nullptr);
    ~SdlGamepadDevice() override;

    bool isConnected() const override { return m_handle != nullptr; }
    QString name() const override { return m_name; }
    int axisCount() const override { return int(m_axes.size()); }
    int buttonCount() const override { return int(m_buttons.size()); }
    double axis(int index) const override { return m_axes.value(index); }
    bool button(int index) const override { return m_buttons.value(index); }
    QString backendError() const override { return m_error; }

    // SDL is polled every kSamplePollMs while a device is open, every kIdlePollMs while
    // waiting for one to be plugged in (0: not polled, SDL failed to start).
    static constexpr int kSamplePollMs = 10;
    static constexpr int kIdlePollMs = 250;
    int pollIntervalMs() const;

private:
    void followDevice(); // the poll interval for having a device or not
    void poll();
    void openDevice(int deviceIndex);
    void closeDevice();
    void setAxis(int index, double value);
    void setButton(int index, bool pressed);

    QTimer m_timer;
    QString m_error;
    QString m_name;
    void* m_handle = nullptr; // SDL_GameController* or SDL_Joystick*
    bool m_isController = false;
    int m_instance = -1;
    QVector<double> m_axes;
    QVector<bool> m_buttons;
};

} // namespace stepdeck::ui
#endif
