#pragma once
#include "NanotecClosedLoopRun.h"
#include "NanotecController.h"
#include "model/Axis.h"
#include "model/ClosedLoop.h"
#include "model/CommandResult.h"
#include <QElapsedTimer>
#include <QMap>
#include <QObject>
#include <QVariantMap>
#include <optional>

namespace stepdeck::nanotec {

// The closed-loop commissioning of a Nanotec drive (manual 8.1, operations of
// model/ClosedLoop.h): motor data and encoder check, the calibration run (mode 101, "!101"),
// the special closed-loop reference run (mode 8, "!8") and ":CL_enable". It drives the drive
// through the controller's own exchange steps (setting, read-back, 'A' with its lost-echo
// rule) and its status bookkeeping, so a run is tracked motion like any other: the drive's
// motionPending keeps moves and jogs refused, STOP/PANIC/link loss send 'S' to it (6.2), and
// the axis is unreferenced from the start of a run (the motor turns).
//
// Readings where the manual is silent (the simulator, NanotecDriveClosedLoop.h, does the same):
// - A run is the mode set with '!' and started with 'A' (6.1 "Startet die Fahrt mit den
//   aktuell eingestellten Parametern"); its end is the ready bit of '$' (5.21 bit 0). Neither
//   8 nor 101 fits the status word's mode bits 4-6, so the host tracks which run is on.
// - Its result is the position error bit (5.21 bit 2) with the error memory's last entry
//   (5.15, e.g. ERROR_QEI): set means the run failed; clear means it succeeded. Progress is
//   what the drive shows while it turns: busy, position 'C' and encoder position 'I'.
// - Calibration is refused while the motor data cannot work (8.6-8.8 allow only pole pairs 50
//   or 100, increments 1600 or 2000, one revolution) or closed loop is on.
// - The closed-loop reference run goes in the direction of 'd' (6.12), as every reference run
//   of 6.6; it ends on the reference position: the axis is referenced at 0 afterwards.
// - After either run the mode read before it is set again (only 1..6 count; otherwise 1), so
//   later moves and the status word's mode bits are as before.
// - The drive cannot report whether it is calibrated or was referenced since power-on: the
//   host only knows what it saw in this connection and says so.
class NanotecClosedLoop : public QObject
{
    Q_OBJECT
public:
    explicit NanotecClosedLoop(NanotecController* controller);

    static bool isOperation(const QString& name);
    // One of the operations of model/ClosedLoop.h for the drive of `axis`.
    void operation(RequestId id, const QString& name, Axis axis, const QVariantMap& args);
    // STOP, PANIC, link loss, close: every run ends now; its request fails with kind. The
    // controller sends the stop itself ('S' to every drive with motion pending).
    void abortAll(ErrorKind kind, const QString& why) { m_run.abortAll(kind, why); }
    bool isRunning(Axis axis) const { return m_run.find(axis) != nullptr; }
    // For DriveStatus::detail: "calibration run 2.1 s" while a run is on, else empty.
    QString runDetail(Axis axis) const { return m_run.runDetail(axis); }

private:
    friend class NanotecClosedLoopRun; // records what a run did (memoryOf)
    using Kind = ClosedLoopRunKind;
    struct Memory // what this connection saw of one drive
    {
        QString calibration = closedloop::kResultNone;
        QString reference = closedloop::kResultNone;
        std::optional<bool> enabled;
    };

    void check(RequestId id, Axis axis);
    void start(RequestId id, Axis axis, Kind kind, int direction);
    void enable(RequestId id, Axis axis, bool on);
    QVariantMap state(Axis axis) const;
    QString& memoryOf(Axis axis, Kind kind);
    QStringList motorDataProblems(const QVariantMap& data) const;
    // Reads pole pairs, encoder increments and revolutions, closed loop on/off (wire values).
    QList<Step> readMotorData(Axis axis, std::shared_ptr<QVariantMap> data);
    static qint64 restorableMode(qint64 mode);

    NanotecController* m_ctl;
    QMap<Axis, Memory> m_memory;
    NanotecClosedLoopRun m_run{m_ctl, *this};
};

} // namespace stepdeck::nanotec
