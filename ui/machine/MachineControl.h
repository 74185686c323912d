#pragma once
#include "messages/StatusMessages.h"
#include "model/CommandResult.h"
#include <QMap>
#include <QObject>
#include <QStringList>

namespace stepdeck::ui {

class MachineContext;
class MachineStopWatch;

// What the main window does with a machine of several controllers (issue 19), kept out of
// MainWindow: opening a machine file (an invalid one is reported naming the field, nothing
// is opened), STOP and PANIC to every controller at once with a message that names the
// controllers that cannot be stopped, the failure of one controller, and the window title.
// After STOP or PANIC the message first says it was sent, then -- only once a status read of
// every controller after its request reported standstill (MachineStopWatch) -- that the
// machine stopped, or names the controller that did not confirm and why. That "not confirmed"
// line (issue 47 item 7) is no longer shown once the devices have confirmed standstill since:
// a later status read (MachineStopWatch::confirmedLater), a reference run that ended well, or
// a later STOP or PANIC that was confirmed.
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
    static StatusMessages::Owner ownerOf(Kind kind); // where its messages go
    void follow(Kind kind, const QMap<QString, RequestId>& requests, const QStringList& stoppable,
                const QStringList& unstoppable);
    void onConfirmed(const QStringList& controllers);
    void onNotConfirmed(const QString& controllerId, const QString& reason);
    void onConfirmedLater(const QStringList& controllers);
    void onMachineChanged();
    // The "not confirmed" line, while it is still the one its owner shows (nothing replaced it
    // and it has not expired).
    bool notConfirmedShown() const;
    void clearNotConfirmed(); // the line goes (if still shown) and is no longer followed

    MachineContext* m_context;
    StatusMessages* m_messages;
    MachineStopWatch* m_watch;
    // The watch under way: what was stopped, and what could not be (for the final text).
    Kind m_kind = Kind::Stop;
    QStringList m_stoppable;
    QStringList m_unstoppable;
    // The "not confirmed" line shown last (empty text: none followed).
    struct NotConfirmed
    {
        Kind kind = Kind::Stop;
        StatusMessages::Owner owner = StatusMessages::Owner::General;
        QString text;
        QStringList controllers; // those that had not confirmed
    };
    NotConfirmed m_notConfirmed;
    QMetaObject::Connection m_referenceConnection; // the open machine's referenceFinished
};

} // namespace stepdeck::ui
