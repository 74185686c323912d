#include "ElabCtlLine.h"
#include <QCoreApplication>
#include <memory>

namespace stepdeck::elab {

namespace {
constexpr int kStatusRetries = 2;
} // namespace

ElabCtlLine::ElabCtlLine(ElabExchangeQueue& queue, MachineStatus& status, ElabCtlHooks hooks)
    : m_queue(queue), m_status(status), m_hooks(std::move(hooks))
{}

void ElabCtlLine::setMachineWord(quint16 word)
{
    m_machineWord = word;
    ElabCtlStatusMapper::applyMachineState(m_status, word, m_hostPanic);
}

void ElabCtlLine::setHostPanic(bool on)
{
    m_hostPanic = on;
    m_status.panic = on || (m_machineWord & machine::PanicStop);
}

bool ElabCtlLine::stale(const Op& op)
{
    if (op.epoch == m_epoch)
        return false;
    m_hooks.fail(op.id, ErrorKind::Cancelled, tr("cancelled by a stop, panic or reset"));
    return true;
}

ElabExchange ElabCtlLine::exchange(RequestId owner, const QByteArray& frame, Expect expect)
{
    ElabExchange ex;
    ex.owner = owner;
    ex.frame = frame;
    ex.expect = expect;
    return ex;
}

void ElabCtlLine::submit(ElabExchange ex, bool continuation)
{
    if (continuation)
        m_queue.enqueueNext(std::move(ex));
    else
        m_queue.enqueue(std::move(ex));
}

void ElabCtlLine::chain(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
                        ErrorFn failed)
{
    if (steps.isEmpty()) {
        done();
        return;
    }
    ElabExchange ex = steps.takeFirst();
    auto handler = ex.onReply;
    ex.onReply = [this, handler, steps, done, failed](const Reply& r) {
        if (handler)
            handler(r);
        chain(steps, true, done, failed);
    };
    ex.onError = failed;
    submit(std::move(ex), continuation);
}

void ElabCtlLine::pipeline(QList<ElabExchange> steps, bool continuation, std::function<void()> done,
                           ErrorFn failed)
{
    // The steps go out back to back (ElabExchange::pipelineGroup). A step's reply is applied only
    // while no step before it failed, so a sequence ends once: done or failed.
    struct Progress
    {
        qsizetype left = 0;
        bool failed = false;
    };
    auto progress = std::make_shared<Progress>(Progress{steps.size(), false});
    const quint64 group = ElabExchangeQueue::newPipelineGroup();
    for (ElabExchange& ex : steps) {
        ex.pipelineGroup = group;
        ex.onReply = [progress, handler = ex.onReply, done](const Reply& r) {
            if (progress->failed)
                return;
            if (handler)
                handler(r);
            if (--progress->left == 0)
                done();
        };
        ex.onError = [progress, failed](ErrorKind kind, const QString& message) {
            if (progress->failed)
                return;
            progress->failed = true;
            failed(kind, message);
        };
    }
    if (continuation) {
        m_queue.enqueueNext(std::move(steps)); // in order, none written before all are queued
    } else {
        for (ElabExchange& ex : steps)
            m_queue.enqueue(std::move(ex));
    }
}

void ElabCtlLine::readStatus(RequestId owner, StatusRead how, std::function<void()> done,
                             ErrorFn failed)
{
    ElabExchange ht = exchange(owner, encode::requestAxeState(), Expect::AxeState);
    ht.onReply = [this](const Reply& r) {
        m_axeWord = r.axeState;
        ElabCtlStatusMapper::applyAxeState(m_status, r.axeState);
    };
    ElabExchange enq = exchange(owner, encode::requestMachineState(), Expect::MachineState);
    enq.onReply = [this](const Reply& r) { setMachineWord(r.machineState); };
    QList<ElabExchange> words{ht, enq};
    QList<ElabExchange> extras;
    if (how.temperature) {
        ElabExchange etb = exchange(owner, encode::requestTemperature(), Expect::Temperature);
        etb.onReply = [this](const Reply& r) {
            ElabCtlStatusMapper::applyTemperature(m_status, r.temperature);
        };
        extras << etb;
    }
    if (how.startButton) {
        // RequestStart: <ACK> pressed, <NAK> not pressed -- a NAK here is an answer, not a fault.
        ElabExchange lf = exchange(owner, encode::requestStart(), Expect::AckNak);
        lf.onReply = [this](const Reply& r) { m_status.startButton = r.kind == Reply::Kind::Ack; };
        extras << lf;
    }
    for (QList<ElabExchange>* list : {&words, &extras}) {
        for (ElabExchange& ex : *list) {
            ex.poll = how.poll;
            ex.tolerateStray = how.tolerant;
            ex.droppable = how.beforeCommand && owner != 0;
            ex.retries = kStatusRetries; // idempotent: noise costs a retry, not a fault
        }
    }
    // A poll's done() may write the next poll (ElabController::startPoll): that goes first, the
    // publication after. A request's result follows its status publication.
    // The motion bookkeeping runs once every read of this status read is in: pipelined, the
    // <ENQ> reply can come before a re-asked <HT> (a lost first reply), and words of two
    // moments must not be judged together.
    auto finish = [this, done, poll = how.poll] {
        m_hooks.statusRead();
        if (poll) {
            done();
            m_hooks.publish();
            return;
        }
        m_hooks.publish();
        done();
    };
    if (how.tolerant) {
        // After a panic, reset or connect late replies may still come: one at a time, so a
        // stray is skipped instead of being taken for the next read's reply.
        chain(words + extras, how.continuation, finish, failed);
        return;
    }
    // Issue 21: the reads back to back, each before the first reply.
    pipeline(words + extras, how.continuation, finish, failed);
}

void ElabCtlLine::sendCommand(const Op& op, const QByteArray& frame, std::function<void()> onAck,
                              bool continuation)
{
    ElabExchange ex = exchange(op.id, frame, Expect::AckNak);
    ex.onReply = [this, op, frame, onAck](const Reply& r) {
        if (r.kind == Reply::Kind::Ack)
            onAck();
        else
            failWithNak(op, frame);
    };
    ex.onError = [this, op](ErrorKind kind, const QString& message) {
        m_hooks.fail(op.id, kind, message);
    };
    submit(std::move(ex), continuation);
}

void ElabCtlLine::failWithNak(const Op& op, const QByteArray& frame)
{
    // "Im Falle eines <NAK> ist es am besten man liest beide Status Informationen mit
    // RequestAxeState und RequestMachineState aus".
    const QString command = toMnemonics(frame);
    StatusRead how;
    how.continuation = true;
    readStatus(
        op.id, how,
        [this, op, command] {
            m_hooks.fail(op.id, ErrorKind::Nak,
                         tr("%1 answered NAK; machine state %2: %3; axe state %4: %5")
                             .arg(command)
                             .arg(m_machineWord, 4, 16, QLatin1Char('0'))
                             .arg(describeMachineState(m_machineWord))
                             .arg(m_axeWord, 2, 16, QLatin1Char('0'))
                             .arg(describeAxeState(m_axeWord)));
        },
        [this, op, command](ErrorKind, const QString& why) {
            m_hooks.fail(op.id, ErrorKind::Nak,
                         tr("%1 answered NAK; the status could not be read: %2").arg(command, why));
        });
}

void ElabCtlLine::preflight(RequestId id, ElabCtlStatusMapper::Rule rule,
                            std::function<void(Op)> then)
{
    // "Deshalb muss vor jedem Move Kommando solange mit RequestAxeState gepollt werden, bis der
    // letzte Befehl komplett ausgeführt ist ... Ausserdem darf das LimitSwitch Flag nicht aktiv
    // sein." The command follows the status read directly (continuation), so nothing else can
    // start in between. Not idle: refused at once rather than waiting (callers that want to
    // wait poll the status themselves).
    const Op first = op(id);
    StatusRead how;
    how.beforeCommand = true;
    readStatus(
        id, how,
        [this, first, rule, then] {
            if (stale(first))
                return;
            const QString refusal = ElabCtlStatusMapper::refusal(rule, m_machineWord, m_axeWord);
            if (!refusal.isEmpty()) {
                m_hooks.fail(first.id, ErrorKind::Refused, refusal);
                return;
            }
            then(first);
        },
        [this, id](ErrorKind kind, const QString& why) { m_hooks.fail(id, kind, why); });
}

} // namespace stepdeck::elab
