#pragma once
#include "jog/JogInputSource.h"
#include "jog/JogResponse.h"
#include <QElapsedTimer>
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
// Proof of holding: a device sample (GamepadDevice::sampled() or a change) with the dead-man
// held, no older than kSampleWindowMs; a device that stops delivering samples counts as
// released. After STOP, PANIC or focus loss the pad is latched until the sticks are back in
// their dead zone or the dead-man button is released.
class GamepadJogSource : public JogInputSource
{
    Q_OBJECT
public:
    static constexpr int kSampleWindowMs = 150; // SDL samples every 10 ms

    explicit GamepadJogSource(GamepadDevice* device, QObject* parent = nullptr);

    QString sourceName() const override { return tr("Gamepad"); }
    SlotVelocities heldDeflection() override;
    void latch() override;
    bool isLatched() const { return m_latched; }
    GamepadDevice* device() const { return m_device; }

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void setDeadmanButton(int button); // -1: none (not recommended; motion needs no button)
    int deadmanButton() const { return m_deadman; }
    bool deadmanHeld() const;
    void setResponse(const JogResponse& response);
    JogResponse response() const { return m_response; }
    void setBinding(JogSlot axis, const StickBinding& binding);
    StickBinding binding(JogSlot axis) const { return m_bindings.value(axis); }
    AxisCalibration calibration(int rawAxis) const { return m_calibration.value(rawAxis); }

    void startCalibration(); // takes the current stick positions as rest, learns extents
    void finishCalibration();
    bool isCalibrating() const { return m_calibrating; }

    // The stick deflection now (dead-man held), whether or not it is proven or latched.
    SlotVelocities fractions() const { return m_last; }
    void loadSettings();
    void saveSettings() const;

Q_SIGNALS:
    void stateChanged(); // connection, dead-man or fractions changed (panel refresh)

private:
    void update();
    void onSample();
    bool isProven() const;
    SlotVelocities readSticks() const;

    QPointer<GamepadDevice> m_device;
    bool m_enabled = true;
    int m_deadman = 9; // SDL_CONTROLLER_BUTTON_LEFTSHOULDER
    JogResponse m_response;
    QMap<JogSlot, StickBinding> m_bindings;
    QMap<int, AxisCalibration> m_calibration;
    bool m_calibrating = false;
    SlotVelocities m_last;
    bool m_latched = false;
    QElapsedTimer m_clock;
    qint64 m_provenMs = -1; // last sample with the dead-man held
};

} // namespace stepdeck::ui
