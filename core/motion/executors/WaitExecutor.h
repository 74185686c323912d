#pragma once
#include "model/CommandResult.h"
#include "motion/MotionCommand.h"
#include <QObject>
#include <QPointer>
#include <QTimer>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::motion {

// The executor of the waits (issue 49 item 3): a Dwell (G4, a drilling cycle's P) and a
// WaitInput (M66). A dwell lasts at least its seconds from push(): from the previous command's
// confirmation to the next one's first byte. An input wait ends when a status read asked for
// at push() or after shows the machine's input at its level (so that a level read before it, a
// part sensor of the previous cycle, does not end it), or fails after its seconds
// (ErrorKind::Timeout). The machine's inputs count as SwitchExecutor::input says. No Widgets.
class WaitExecutor : public QObject
{
    Q_OBJECT
public:
    explicit WaitExecutor(machine::Machine* machine, QObject* parent = nullptr);

    // A Dwell or a WaitInput; any other command is none of this executor's.
    void push(const MotionCommand& command);
    void cancel(); // nothing more is reported

Q_SIGNALS:
    // The wait is over (ok), or why not: the machine has no such input (Unsupported), its
    // status read failed (the read's kind), or the level did not come in time (Timeout).
    void finished(bool ok, stepdeck::ErrorKind kind, const QString& message);

private:
    void startInput(const WaitInput& wait);
    void checkInput();
    void onRequestFinished(const QString& controllerId, const CommandResult& result);
    void fail(ErrorKind kind, const QString& message);

    QPointer<machine::Machine> m_machine;
    QTimer m_dwell;
    QTimer m_timeout;
    int m_input = 0; // the machine input waited for (0: none)
    bool m_high = true;
    QString m_controller; // its controller
    int m_number = 0;     // and its number there
    RequestId m_read = 0; // the status read its level must be newer than
};

} // namespace stepdeck::motion
