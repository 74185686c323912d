#pragma once
#include "jog/JogInputSource.h"
#include "jog/JogResponse.h"
#include <QPointer>

namespace stepdeck::ui {

class GamepadDevice;

// Calibration of one raw stick axis: rest position and the extents seen while calibrating.
struct AxisCalibration
{
    double centre = 0;
    double minimum = -1;
    double maximum = 1;
    double apply(double raw) const; // -> -1..1 around the rest position
};

// Which stick axis drives which machine axis.
struct StickBinding
{
    int index = -1; // raw axis of the device; -1: not mapped
    bool invert = false;
};

// A physical gamepad as a jog source. Motion only while the dead-man button is held:
// releasing it, unplugging the device or disabling the source releases every axis at once
// (the core ramps them to zero). Stick values pass calibration, dead zone and response curve.
class GamepadJogSource : public JogInputSource
{
    Q_OBJECT
public:
    explicit GamepadJogSource(GamepadDevice* device, QObject* parent = nullptr);

    QString sourceName() const override { return tr("Gamepad"); }
    GamepadDevice* device() const { return m_device; }

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void setDeadmanButton(int button); // -1: none (not recommended; motion needs no button)
    int deadmanButton() const { return m_deadman; }
    bool deadmanHeld() const;
    void setResponse(const JogResponse& response);
    JogResponse response() const { return m_response; }
    void setBinding(Axis axis, const StickBinding& binding);
    StickBinding binding(Axis axis) const { return m_bindings.value(axis); }
    AxisCalibration calibration(int rawAxis) const { return m_calibration.value(rawAxis); }

    void startCalibration(); // takes the current stick positions as rest, learns extents
    void finishCalibration();
    bool isCalibrating() const { return m_calibrating; }

    AxisVelocities fractions() const { return m_last; }
    void loadSettings();
    void saveSettings() const;

Q_SIGNALS:
    void stateChanged(); // connection, dead-man or fractions changed (panel refresh)

private:
    void update();
    void publish(const AxisVelocities& fractions);

    QPointer<GamepadDevice> m_device;
    bool m_enabled = true;
    int m_deadman = 9; // SDL_CONTROLLER_BUTTON_LEFTSHOULDER
    JogResponse m_response;
    QMap<Axis, StickBinding> m_bindings;
    QMap<int, AxisCalibration> m_calibration;
    bool m_calibrating = false;
    AxisVelocities m_last;
};

} // namespace stepdeck::ui
