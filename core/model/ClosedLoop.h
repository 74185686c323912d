#pragma once
#include <QLatin1String>

// The closed-loop commissioning of a drive with an encoder (Capabilities::closedLoop; Nanotec
// manual 8.1) as model operations. Every operation name and result key is defined here and
// nowhere else, so that GUI, CLI and adapter cannot drift apart.
//
// The technician's order (manual 8.1, "Wichtige Bedingungen"):
//   1. kCheck      motor data (pole pairs, encoder increments and revolutions) and encoder
//   2. kCalibrate  calibration run, once for every newly connected motor (the motor turns)
//   3. kReference  the special closed-loop reference run, once after every power-on (turns)
//   4. kEnable     closed loop on; the drive ignores it without 3 (and 2 for a new motor)
// Runs (2, 3) finish their request when the drive is ready again, with the result read back;
// kState reports a run's progress meanwhile. STOP, PANIC and a lost link end a run at once:
// its request fails (Cancelled or LinkDown) and the drive counts as not calibrated.
namespace stepdeck::closedloop {

// {axis} -> map: kMotorPolePairs, kEncoderIncrements, kEncoderRevolutions, kStepAngle,
// kEnabled, kEncoderPosition, kPosition (all read back now), kProblems (QStringList: why the
// motor data cannot work in closed loop; empty when they fit), plus the kState keys. No motion.
constexpr QLatin1String kCheck("closed-loop-check");
// {axis} -> map of the kState keys, from what the host knows (no bus traffic).
constexpr QLatin1String kState("closed-loop-state");
// {axis} -> when the run has ended: map {kAxis, kDurationMs, kPosition, kEncoderPosition,
// kErrorCode, kErrorName}. Refused (nothing sent) while the motor data cannot work, the drive
// is busy or reports an error, or closed loop is on. A run the drive reports as failed
// finishes as ErrorKind::Nak naming the drive's error.
constexpr QLatin1String kCalibrate("closed-loop-calibrate");
// {axis, direction: -1|1} -> like kCalibrate; afterwards the axis is referenced at 0.
constexpr QLatin1String kReference("closed-loop-reference");
// {axis, on: bool} -> map {kAxis, kEnabled (read back), kParameter (the schema parameter the
// value belongs to)}. VerifyFailed when the drive kept the other value (8.1: it ignores "on"
// without the closed-loop reference run since power-on).
constexpr QLatin1String kEnable("closed-loop-enable");

// Keys of the result maps.
constexpr QLatin1String kAxis("axis");
constexpr QLatin1String kMotorPolePairs("motorPolePairs");
constexpr QLatin1String kEncoderIncrements("encoderIncrements");
constexpr QLatin1String kEncoderRevolutions("encoderRevolutions");
constexpr QLatin1String kStepAngle("stepAngle"); // "0.9" or "1.8" (degrees)
constexpr QLatin1String kEnabled("enabled");     // bool; absent in kState until read
constexpr QLatin1String kEncoderPosition("encoderPosition");
constexpr QLatin1String kPosition("position");
constexpr QLatin1String kProblems("problems");
constexpr QLatin1String kParameter("parameter");
constexpr QLatin1String kDurationMs("durationMs");
constexpr QLatin1String kErrorCode("errorCode");
constexpr QLatin1String kErrorName("errorName");
// kState: kRun is kRunNone, kRunCalibration or kRunReference; while a run is on, kElapsedMs and
// the kPosition / kEncoderPosition last read during it. kCalibration and kReferenceRun are
// kResult* values for what happened in this connection (the drive cannot report either).
constexpr QLatin1String kRun("run");
constexpr QLatin1String kElapsedMs("elapsedMs");
constexpr QLatin1String kCalibration("calibration");
constexpr QLatin1String kReferenceRun("referenceRun");
constexpr QLatin1String kRunNone("none");
constexpr QLatin1String kRunCalibration("calibration");
constexpr QLatin1String kRunReference("reference");
constexpr QLatin1String kResultNone("none"); // not run in this connection
constexpr QLatin1String kResultRunning("running");
constexpr QLatin1String kResultDone("done");
constexpr QLatin1String kResultFailed("failed");   // the drive reported an error
constexpr QLatin1String kResultAborted("aborted"); // stop, panic, link loss, timeout

} // namespace stepdeck::closedloop
