#pragma once
#include "model/CommandResult.h"
#include <QMap>
#include <QObject>
#include <QStringList>

namespace stepdeck::ui {

class MachineContext;
class MachineStopWatch;
class StatusMessages;

// What the main window does with a machine of several controllers (issue 19), kept out of
// MainWindow: opening a machine file (an invalid one is reported naming the field, nothing
// is opened), STOP and PANIC to every controller at once with a message that names the
// controllers that cannot be stopped, the failure of one controller, and the window title.
// After STOP or PANIC the message first says it was sent, then -- only once every controller
// acknowledged its request and reported standstill (MachineStopWatch) -- that the machine
// stopped, or names the controller that did not confirm and why.
class MachineControl : public QObject
{
    Q_OBJECT
public:
    MachineControl(MachineContext* context, StatusMessages* messages, QObject* parent = nullptr);

    // Reads, validates and opens the machine; its links are not opened (connect() does).
    // False with the message shown when the file is invalid or cannot be read.
    bool open(const QString& path);
    void connect();
    // Posted to every controller before any is waited for (Machine::stop/panic).
    void stop();
    void panic();
    // The controllers of the open machine that are connected, split by whether they have a
    // stop command (Capabilities::stopCommand).
    void connectedControllers(QStringList* stoppable, QStringList* unstoppable) const;
    // "StepDeck — <machine name>", or an empty text without a machine.
    QString title() const;
    // A stop or panic is still waiting for its controllers to confirm standstill; its final
    // message is still to come.
    bool isFollowingStop() const;

private:
    QString notStoppedText(const QStringList& unstoppable) const;
    enum class Kind { Stop, Panic };
    void follow(Kind kind, const QMap<QString, RequestId>& requests, const QStringList& stoppable,
                const QStringList& unstoppable);
    void onConfirmed();
    void onNotConfirmed(const QString& controllerId, const QString& reason);

    MachineContext* m_context;
    StatusMessages* m_messages;
    MachineStopWatch* m_watch;
    // The watch under way: what was stopped, and what could not be (for the final text).
    Kind m_kind = Kind::Stop;
    QStringList m_stoppable;
    QStringList m_unstoppable;
};

} // namespace stepdeck::ui
