#pragma once
#include "ElabCtlStatusMapper.h"
#include "ElabExchangeQueue.h"
#include "model/MachineStatus.h"
#include <QCoreApplication>
#include <functional>

namespace stepdeck::elab {

// What the E-LAB helpers need from the controller (Controller's protected members).
struct ElabCtlHooks
{
    std::function<void(RequestId, const QVariant&)> ok;
    std::function<void(RequestId, ErrorKind, const QString&)> fail;
    std::function<void()> publish;              // statusChanged
    std::function<void()> statusRead;           // both words were read: motion bookkeeping
    std::function<bool(RequestId)> requireLink; // false: the request was failed LinkDown
    std::function<void(const QString&)> error;  // errorOccurred
    std::function<void()> streamChanged;        // a <DC2> stream started or ended (may be null)
};

// The request sequences of the E-LAB adapter, built from exchanges on the queue: status
// reads, commands answered <ACK>/<NAK> (a NAK reads both status words and reports their
// decoded bits) and the standstill pre-flight the manual demands before motion. The steps of
// one sequence run back to back: each next step is queued ahead of other work. A status read
// sends its requests pipelined (all before the first reply, issue 21).
class ElabCtlLine
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::ElabCtlLine)
public:
    using ErrorFn = std::function<void(ErrorKind, const QString&)>;
    struct Op
    {
        RequestId id = 0;
        quint64 epoch = 0; // stop, panic, reset and link loss start a new epoch
    };
    struct StatusRead
    {
        bool poll = false;
        bool continuation = false; // runs ahead of queued work (next step of a sequence)
        bool tolerant = false;     // skip stray replies (after panic, reset, connect)
        bool temperature = false;
        bool startButton = false;
        // The read only decides whether a command follows (a pre-flight): a stop drops it with
        // that command. Every other read just observes, like a poll: a stop leaves it queued,
        // so the caller gets what the board reports (after the stop, which overtakes it).
        bool beforeCommand = false;
    };

    ElabCtlLine(ElabExchangeQueue& queue, MachineStatus& status, ElabCtlHooks hooks);

    ElabExchangeQueue& queue() { return m_queue; }
    MachineStatus& status() { return m_status; }
    const ElabCtlHooks& hooks() const { return m_hooks; }

    quint16 machineWord() const { return m_machineWord; }
    quint8 axeWord() const { return m_axeWord; }
    void setMachineWord(quint16 word); // also maps it onto the status
    // The host sent ForcePanicStop; status.panic stays set until cleared.
    bool hostPanic() const { return m_hostPanic; }
    void setHostPanic(bool on);

    Op op(RequestId id) const { return Op{id, m_epoch}; }
    quint64 epoch() const { return m_epoch; }
    void newEpoch() { ++m_epoch; }
    // true (and the request finished Cancelled) when a stop/panic/reset came in between.
    bool stale(const Op& op);

    static ElabExchange exchange(RequestId owner, const QByteArray& frame, Expect expect);
    void submit(ElabExchange ex, bool continuation);
    void chain(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
               ErrorFn failed);
    // The steps go out back to back (pipelined reads), not each after the previous reply.
    void pipeline(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
                  ErrorFn failed);
    void readStatus(RequestId owner, StatusRead how, std::function<void()> done, ErrorFn failed);
    void sendCommand(const Op& op, const QByteArray& frame, std::function<void()> onAck,
                     bool continuation = true);
    void failWithNak(const Op& op, const QByteArray& frame);
    // Reads RequestAxeState and RequestMachineState, refuses with the rule's reason or runs
    // `then` as the very next step.
    void preflight(RequestId id, ElabCtlStatusMapper::Rule rule, std::function<void(Op)> then);

private:
    ElabExchangeQueue& m_queue;
    MachineStatus& m_status;
    ElabCtlHooks m_hooks;
    quint16 m_machineWord = 0;
    quint8 m_axeWord = 0;
    bool m_hostPanic = false;
    quint64 m_epoch = 1;
};

} // namespace stepdeck::elab
