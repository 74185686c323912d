#pragma once
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QMap>
#include <QObject>
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
// (issue 19; "never claim a stop the device did not confirm"). A controller counts as
// stopped only once its request was acknowledged and a status read asked for after that
// shows nothing moving (motionIn); a read that still shows motion is repeated
// with the controller's next status. Ends with confirmed() once every controller did, or
// with notConfirmed() for the first one that refused the request, lost its link or did not
// report standstill within kConfirmMs. Host-side only; it never sends a stop itself.
class MachineStopWatch : public QObject
{
    Q_OBJECT
public:
    static constexpr int kConfirmMs = 5000;
    // Whether anything may be moving as far as the status tells (axes, jog rates, busy, a
    // silent drive's unconfirmed motion).
    static bool motionIn(const MachineStatus& status);

    explicit MachineStopWatch(QObject* parent = nullptr);

    // requests: controller id -> its stop request (controllers without one are left out by
    // the caller). Replaces any watch under way.
    void watch(const machine::Machine* machine, const QMap<QString, RequestId>& requests);
    void cancel(); // no claim either way (the machine was closed, a new stop was sent)
    bool isWatching() const { return !m_watched.isEmpty(); }

Q_SIGNALS:
    void confirmed(const QStringList& controllers);
    void notConfirmed(const QString& controllerId, const QString& reason);

private:
    struct Watched
    {
        ControllerSession* session = nullptr;
        RequestId stop = 0;
        RequestId read = 0;    // the status read asked for after the stop was acknowledged
        bool answered = false; // the stop request was acknowledged
        bool stopped = false;  // a read after the acknowledgement showed standstill
    };
    void onResult(const QString& id, const CommandResult& result);
    void onStatus(const QString& id);
    void fail(const QString& id, const QString& reason);

    QMap<QString, Watched> m_watched;
    QList<QMetaObject::Connection> m_connections;
    QTimer m_deadline;
};

} // namespace stepdeck::ui
