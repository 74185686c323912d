#include "SdlGamepadDevice.h"
#include <QCoreApplication>

#ifdef STEPDECK_HAVE_SDL2
#include <SDL.h>

namespace stepdeck::ui {

namespace {
constexpr int kControllerAxes = SDL_CONTROLLER_AXIS_MAX;
constexpr int kControllerButtons = SDL_CONTROLLER_BUTTON_MAX;
double scale(Sint16 v)
{
    return qBound(-1.0, v / 32767.0, 1.0);
}
} // namespace

SdlGamepadDevice::SdlGamepadDevice(QObject* parent) : GamepadDevice(parent)
{
    // No SDL window: without this hint SDL drops joystick events of an unfocused app.
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    // SDL's own SIGINT/SIGTERM handlers would turn the signals into SDL_QUIT events nobody
    // reads, so `kill` and logout could not end StepDeck: the application handles them itself
    // (app/gui/main.cpp). Must be set before any SDL_Init*.
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER | SDL_INIT_JOYSTICK) != 0) {
        m_error = tr("SDL could not start its joystick support: %1")
                      .arg(QString::fromUtf8(SDL_GetError()));
        return;
    }
    m_timer.setInterval(kIdlePollMs);
    connect(&m_timer, &QTimer::timeout, this, &SdlGamepadDevice::poll);
    m_timer.start();
    for (int i = 0; i < SDL_NumJoysticks() && !m_handle; ++i)
        openDevice(i);
}

int SdlGamepadDevice::pollIntervalMs() const
{
    return m_timer.isActive() ? m_timer.interval() : 0;
}

void SdlGamepadDevice::followDevice()
{
    // A held stick is sampled every 10 ms; without a device only a plug-in is waited for,
    // which a few polls a second notice as well (SDL queues the device-added event).
    const int interval = m_handle ? kSamplePollMs : kIdlePollMs;
    if (m_timer.interval() != interval)
        m_timer.setInterval(interval);
}

SdlGamepadDevice::~SdlGamepadDevice()
{
    closeDevice();
    if (m_error.isEmpty())
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER | SDL_INIT_JOYSTICK);
}

void SdlGamepadDevice::openDevice(int deviceIndex)
{
    if (m_handle)
        return;
    if (SDL_IsGameController(deviceIndex)) {
        SDL_GameController* c = SDL_GameControllerOpen(deviceIndex);
        if (!c)
            return;
        m_handle = c;
        m_isController = true;
        m_name = QString::fromUtf8(SDL_GameControllerName(c));
        m_instance = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c));
        m_axes = QVector<double>(kControllerAxes, 0.0);
        m_buttons = QVector<bool>(kControllerButtons, false);
    } else {
        SDL_Joystick* j = SDL_JoystickOpen(deviceIndex);
        if (!j)
            return;
        m_handle = j;
        m_isController = false;
        m_name = QString::fromUtf8(SDL_JoystickName(j));
        m_instance = SDL_JoystickInstanceID(j);
        m_axes = QVector<double>(qMax(0, SDL_JoystickNumAxes(j)), 0.0);
        m_buttons = QVector<bool>(qMax(0, SDL_JoystickNumButtons(j)), false);
    }
    followDevice();
    Q_EMIT connectedChanged(true);
}

void SdlGamepadDevice::closeDevice()
{
    if (!m_handle)
        return;
    if (m_isController)
        SDL_GameControllerClose(static_cast<SDL_GameController*>(m_handle));
    else
        SDL_JoystickClose(static_cast<SDL_Joystick*>(m_handle));
    m_handle = nullptr;
    m_instance = -1;
    m_axes.fill(0.0);
    m_buttons.fill(false);
    followDevice();
    Q_EMIT connectedChanged(false);
}

void SdlGamepadDevice::setAxis(int index, double value)
{
    if (index < 0 || index >= m_axes.size() || m_axes[index] == value)
        return;
    m_axes[index] = value;
    Q_EMIT axisChanged(index, value);
}

void SdlGamepadDevice::setButton(int index, bool pressed)
{
    if (index < 0 || index >= m_buttons.size() || m_buttons[index] == pressed)
        return;
    m_buttons[index] = pressed;
    Q_EMIT buttonChanged(index, pressed);
}

void SdlGamepadDevice::poll()
{
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
        switch (e.type) {
        case SDL_JOYDEVICEADDED:
            openDevice(e.jdevice.which);
            break;
        case SDL_JOYDEVICEREMOVED:
            if (e.jdevice.which == m_instance)
                closeDevice();
            break;
        case SDL_CONTROLLERAXISMOTION:
            if (m_isController && e.caxis.which == m_instance)
                setAxis(e.caxis.axis, scale(e.caxis.value));
            break;
        case SDL_CONTROLLERBUTTONDOWN:
        case SDL_CONTROLLERBUTTONUP:
            if (m_isController && e.cbutton.which == m_instance)
                setButton(e.cbutton.button, e.cbutton.state == SDL_PRESSED);
            break;
        case SDL_JOYAXISMOTION:
            if (!m_isController && e.jaxis.which == m_instance)
                setAxis(e.jaxis.axis, scale(e.jaxis.value));
            break;
        case SDL_JOYBUTTONDOWN:
        case SDL_JOYBUTTONUP:
            if (!m_isController && e.jbutton.which == m_instance)
                setButton(e.jbutton.button, e.jbutton.state == SDL_PRESSED);
            break;
        default:
            break;
        }
    }
    if (m_handle)
        Q_EMIT sampled(); // SDL_PollEvent pumped the device: its state is fresh
}

GamepadDevice* createSystemGamepadDevice(QObject* parent)
{
    return new SdlGamepadDevice(parent);
}

} // namespace stepdeck::ui

#else // no SDL2

namespace stepdeck::ui {

namespace {
class NoGamepadDevice : public GamepadDevice
{
public:
    using GamepadDevice::GamepadDevice;
    bool isConnected() const override { return false; }
    QString name() const override { return {}; }
    int axisCount() const override { return 0; }
    int buttonCount() const override { return 0; }
    double axis(int) const override { return 0; }
    bool button(int) const override { return false; }
    QString backendError() const override
    {
        return QCoreApplication::translate("stepdeck::ui::SdlGamepadDevice",
                                           "This build has no gamepad support (SDL2 was not "
                                           "found when it was built).");
    }
};
} // namespace

GamepadDevice* createSystemGamepadDevice(QObject* parent)
{
    return new NoGamepadDevice(parent);
}

} // namespace stepdeck::ui

#endif
