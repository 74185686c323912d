#pragma once
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

namespace stepdeck {
class ControllerSession;
}
namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::ui {

// Follows the stop (or panic) requests Machine::stop()/panic() returned, one per controller
// (issue 19; issue 47 item 7: "never claim a stop the device did not confirm, and never claim
// a failure when the device did confirm standstill"). A controller counts as stopped only once
// a status read asked for after its stop request ended shows nothing moving (motionIn: every
// axis standing, MachineStatus::motionUnconfirmed false) -- the device's word, not the
// request's own result:
//  - acknowledged, or ended Cancelled (a newer stop -- a program's or MDI line's abort, a failed
//    move part, a second STOP -- or a status read overtook it): the status decides; a read that
//    still shows motion is repeated with the controller's next status, until kConfirmMs;
//  - refused or failed otherwise (no answer, not confirmed by a drive): one read all the same;
//    standstill confirms, anything else fails at once with the request's reason.
// Ends with confirmed() once every controller did, or with notConfirmed() for the first one
// that failed, lost its link or did not report standstill within kConfirmMs.
// After notConfirmed() the controllers that had not confirmed are read again, at most once per
// kRecheckIntervalMs and for kRecheckMs (as long as the window's "not confirmed" line can
// live): once every one of them shows standstill, confirmedLater() names them, so that line
// does not outlive the device's later word. Host-side only; it never sends a stop itself.
class MachineStopWatch : public QObject
{
    Q_OBJECT
public:
    static constexpr int kConfirmMs = 5000;
    static constexpr int kRecheckIntervalMs = 1000;
    static constexpr int kRecheckMs = 60000; // StatusMessages::kLifetimeMs
    // Whether anything may be moving as far as the status tells (axes, jog rates, busy, a
    // silent drive's unconfirmed motion).
    static bool motionIn(const MachineStatus& status);

    explicit MachineStopWatch(QObject* parent = nullptr);

    // requests: controller id -> its stop request (controllers without one are left out by
    // the caller). Replaces any watch or recheck under way.
    void watch(const machine::Machine* machine, const QMap<QString, RequestId>& requests);
    // No claim either way (the machine was closed, a new stop was sent); ends a recheck too.
    void cancel();
    void stopRechecking(); // the "not confirmed" line is gone (a reference run ended it)
    bool isWatching() const { return !m_watched.isEmpty(); }
    bool isRechecking() const { return !m_recheck.isEmpty(); }
    QStringList rechecking() const { return m_recheck.keys(); } // after notConfirmed()

Q_SIGNALS:
    void confirmed(const QStringList& controllers);
    void notConfirmed(const QString& controllerId, const QString& reason);
    // After notConfirmed(): every controller that had not confirmed has since reported
    // standstill in a status read asked for after the failure.
    void confirmedLater(const QStringList& controllers);

private:
    struct Watched
    {
        QPointer<ControllerSession> session; // gone with its machine
        RequestId stop = 0;
        RequestId read = 0;      // the status read asked for after the stop request ended
        bool answered = false;   // the stop request ended (acknowledged, overtaken or failed)
        bool stopFailed = false; // it ended with a failure other than Cancelled
        QString stopError;       // its reason then
        bool stopped = false;    // a read after the request's end showed standstill
    };
    struct Recheck
    {
        QPointer<ControllerSession> session;
        RequestId read = 0;
        bool stopped = false;
    };
    void onResult(const QString& id, const CommandResult& result);
    void onStatus(const QString& id);
    void fail(QString id, QString reason); // copies: both may live in m_watched
    void startRecheck(const QMap<QString, ControllerSession*>& sessions);
    void recheckNow();
    void onRecheckResult(const QString& id, const CommandResult& result);
    static MachineStatus statusOf(const CommandResult& result, const ControllerSession* session);

    QMap<QString, Watched> m_watched;
    QList<QMetaObject::Connection> m_connections;
    QTimer m_deadline;
    QMap<QString, Recheck> m_recheck;
    QList<QMetaObject::Connection> m_recheckConnections;
    QTimer m_recheckTick;
    QTimer m_recheckEnd;
};

} // namespace stepdeck::ui
