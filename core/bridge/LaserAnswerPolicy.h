#pragma once
#include "model/MachineStatus.h"
#include "protocols/laser/LaserCodec.h"
#include <QCoreApplication>
#include <optional>

namespace stepdeck::bridge {

// What the laser is told about one axis, or why it is told nothing.
struct LaserAnswer
{
    std::optional<laser::StatusFrame> frame;
    QString withheld; // no frame: why (for the log and the bridge page)
    bool sent() const { return frame.has_value(); }
};

// The bridge's answers to the laser, decided from the controller's status of the axis alone
// (pure). Every status frame of the protocol carries the axis' actual position and the protocol
// has no status for "failed" (manual: '0' reached, '1' end switch, '2' home switch, '3'/'4'
// door). So:
// - A frame goes out only with a position the controller knows: read back or booked, the axis
//   standing (not moving, jogging or of unknown motion), not estimated, and within the laser's
//   0..99999 units. Never a made-up one (00000 for "unknown", or a value clamped into range).
// - The status byte is what the controller reported: '0' only at the target, '1' only at an
//   active limit switch, '2' only at the reference switch or after a reference run.
// - Anything else (a stop short of the target, a lost position, a failed controller) gets no
//   frame; `withheld` says why. The laser then raises its own 60 s timeout alarm, the one
//   failure its manual documents; the bridge logs the reason as an error and its page shows
//   it at once (decision and reasons in docs/cli.md, laser-bridge).
class LaserAnswerPolicy
{
    Q_DECLARE_TR_FUNCTIONS(LaserAnswerPolicy)
public:
    explicit LaserAnswerPolicy(double scale) : m_scale(scale) {}

    // The axis' position in laser units if the laser may be told it; else nullopt and *why.
    std::optional<int> position(const AxisStatus& axis, QString* why) const;

    // A reference run for a home command ended with the axis referenced: '2'.
    LaserAnswer referenced(Axis laserAxis, Axis axis, const AxisStatus& status) const;
    // A reference run ended without referencing the axis.
    LaserAnswer referenceFailed(Axis laserAxis, Axis axis, const AxisStatus& status) const;
    // A move to targetSteps ended (the axis stands): '0' at the target, '1' at a limit switch,
    // '2' at the reference switch.
    LaserAnswer moveEnded(Axis laserAxis, Axis axis, const AxisStatus& status,
                          qint64 targetSteps) const;
    // The controller refused a move at an active limit switch: '1'.
    LaserAnswer refusedAtLimit(Axis laserAxis, Axis axis, const AxisStatus& status) const;
    // The door switch changed: '3' opened, '4' closed, reported by this axis.
    LaserAnswer door(Axis laserAxis, Axis axis, const AxisStatus& status, bool open) const;

private:
    // A frame with the axis' position, or withheld: "<event>, but <why the position is not
    // told>".
    LaserAnswer withPosition(Axis laserAxis, const AxisStatus& status, laser::Status code,
                             const QString& event) const;

    double m_scale = 1.0; // controller steps per laser unit
};

} // namespace stepdeck::bridge
