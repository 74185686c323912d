#pragma once
#include "LaserCodec.h"
#include "controller/Controller.h"
#include <QElapsedTimer>
#include <QTimer>

namespace stepdeck::laser {

// What LaserAxisMotion asks of the adapter (LaserAxisController implements it): finishing
// requests, the status, and the port.
class LaserAxisHost
{
public:
    virtual ~LaserAxisHost() = default;
    virtual Controller& controller() = 0;
    virtual const Controller& controller() const = 0;
    virtual bool requireLink(RequestId id) = 0;
    virtual void succeed(RequestId id, const QVariant& value = {}) = 0;
    virtual void fail(RequestId id, ErrorKind kind, const QString& message) = 0;
    virtual MachineStatus& statusToChange() = 0;
    virtual void publish() = 0;
    virtual void confirmStandstill() = 0;
    // Recorded as traffic and written; false when the port did not take them.
    virtual bool sendFrames(const QByteArray& bytes) = 0;
    virtual void abort(ErrorKind kind, const QString& message) = 0; // the base's abortHostSide
};

// Targets out, status frames in: the motion part of the laser-axis adapter. One target per
// axis at a time (a new one replaces it, as the axes do), each awaited until the axis reports
// or its arrival deadline passes; what the host knows of each axis' motion.
class LaserAxisMotion
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::laser::LaserAxisController)
public:
    LaserAxisMotion(LaserAxisHost& host, const QList<Axis>& axes, QObject* owner);

    void moveRelative(RequestId id, const AxisVector& steps);
    void moveAbsolute(RequestId id, const AxisVector& targets);
    void reference(RequestId id, const QMap<Axis, int>& directions);
    // Command frames typed in the traffic console, already sent: tracked like any target.
    void trackRawCommands(const QByteArray& bytes);
    void resetRawDecoder() { m_rawDecoder.reset(); } // the port (re)opened
    void onStatusFrame(const StatusFrame& frame);

    bool mayBeRunning() const; // a target out, or an axis no longer tracked
    void stopDeadline() { m_deadline.stop(); }
    // The host stops tracking: every awaited axis becomes unconfirmed; returns their names.
    QStringList stopTracking();
    void failPending(ErrorKind kind, const QString& message); // every request waiting
    void updateMachineFlags();

private:
    // What the host knows about one axis' motion.
    struct Track
    {
        bool awaiting = false;    // a target was sent and its status has not come yet
        bool unconfirmed = false; // tracking lost and no status frame since: it may move
        Command command = Command::Move;
        int target = 0;
        qint64 deadlineMs = 0;
    };
    struct Pending
    {
        RequestId id = 0;
        Command command = Command::Move;
        QList<Axis> waiting;
        QStringList endSwitch; // axes that stopped at their end switch
    };

    QString checkTargets(const AxisVector& targets) const;
    void sendTargets(RequestId id, Command command, const QMap<Axis, int>& targets);
    void trackTarget(const CommandFrame& frame, qint64 deadlineMs, bool unconfirmed);
    void replaceTargetOf(Axis axis);
    void settle(Axis axis, bool endSwitch);
    void onDeadline();
    void armDeadline();

    LaserAxisHost& m_host;
    CommandDecoder m_rawDecoder; // command frames in the bytes sent by sendRaw()
    QMap<Axis, Track> m_tracks;
    QList<Pending> m_pending;
    QTimer m_deadline; // parented to the adapter: moves to its thread with it
    QElapsedTimer m_clock;
};

} // namespace stepdeck::laser
