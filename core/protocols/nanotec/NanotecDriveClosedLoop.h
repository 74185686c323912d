#pragma once
#include <QtGlobal>

namespace stepdeck::nanotec {

// The closed-loop side of one simulated drive (manual 8.1): its encoder (which a scenario can
// unplug), the calibration run of mode 101 ("!101"), the special reference run of mode 8
// ("!8") and whether ":CL_enable=1" is accepted. Pure: NanotecDrive feeds it time and moves
// the rotor by what advance() returns.
//
// The manual names the two runs and their purpose but neither their motion nor how the drive
// reports their end. The readings simulated here (and expected by NanotecClosedLoop):
// - Both runs are started like every other run: the mode with '!', then 'A' (6.1). The drive
//   is busy (status bit 0 clear, 5.21) while it runs and ready when it is over.
// - Calibration turns the rotor one revolution forward and back at constant speed, taking
//   calibrationMs(); the position 'C' and encoder 'I' follow the rotor, which is how its
//   progress shows. Without encoder counts the drive gives up after the forward revolution
//   and reports a position error (status bit 2, error memory ERROR_QEI, 5.15).
// - The closed-loop reference run seeks the encoder's index mark at the start frequency in the
//   direction 'd' (like the internal reference run, 6.6 p=3); the index mark is position 0.
//   Without an index within 1.5 revolutions it ends with a position error.
// - 'S' during either run aborts it: the drive is not calibrated (or referenced) then.
// - ":CL_enable=1" is kept only after a successful calibration and a successful closed-loop
//   reference run since power-on; otherwise it is echoed and ignored like any invalid value.
class DriveClosedLoop
{
public:
    enum class Run { None, Calibration, Reference };
    struct Motion
    {
        double steps = 0; // signed rotor travel in this time slice
        double speed = 0; // steps/s, magnitude
        bool finished = false;
        bool failed = false; // finished with a position error
    };

    bool encoderConnected() const { return m_encoder; }
    // An unplugged encoder keeps reporting `lastReading` ('I' stands still, no index mark).
    void setEncoderConnected(bool connected, qint64 lastReading);
    qint64 frozenEncoder() const { return m_frozenEncoder; }
    int calibrationMs() const { return m_calibrationMs; }
    void setCalibrationMs(int ms) { m_calibrationMs = qMax(20, ms); }

    bool calibrated() const { return m_calibrated; }
    bool referencedSincePowerOn() const { return m_referenced; }
    bool acceptsEnable() const { return m_calibrated && m_referenced; }
    Run running() const { return m_run; }

    // physical: rotor position in steps; direction +1/-1 ('d'); referenceSpeed: 'u' (6.8).
    void begin(Run run, qint64 stepsPerRevolution, double physical, int direction,
               double referenceSpeed);
    Motion advance(double dt);
    void interrupt(); // 'S' (6.2) during a run

private:
    Motion calibrationStep(double dt);
    Motion referenceStep(double dt);

    bool m_encoder = true;
    qint64 m_frozenEncoder = 0;
    int m_calibrationMs = 5000;
    bool m_calibrated = false;
    bool m_referenced = false;
    Run m_run = Run::None;
    double m_revolution = 400; // steps
    double m_elapsedMs = 0;
    double m_travelled = 0; // reference run: steps so far
    double m_distance = 0;  // reference run: steps to the index mark
    int m_direction = 1;
    double m_speed = 0;
};

} // namespace stepdeck::nanotec
