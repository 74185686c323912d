#pragma once
#include "MoveRates.h"
#include "model/CommandResult.h"
#include "motion/MotionCommand.h"
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QSet>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::motion {

// The move executor (issue 49 item 3, docs/architecture.md "One motion path"): moves of their
// own -- a G0 or G1, an arc's chord, a drilling cycle's move -- and reference runs (G28 in
// StepDeck, Machine::reference), one at a time through
// Machine::move on any model, the coordinating ones (EMIS IP1, Nanotec: shares of F) and the
// per-move ones (laser axes) alike. Before a feed move each controller of its axes gets its
// model's feed-rate parameter in steps/s per axis (MoveRates::feedRateWrite, docs/programs.md
// "How F maps onto each model"). Where that parameter is also the speed of positioning moves
// (Capabilities::feedRateSetsRapid: Nanotec o, EMIS #E1), the value the device had is read
// before the first write (when the model can read it back) and written back before the next
// positioning move and at the end (restore()), so G0 keeps running at the fast speed; a
// coordinated move turns the model's interpolation on (Capabilities::interpolationParameter).
// The move is sent only once every write was acknowledged; finished() when the machine
// reports the axes arrived, or why not. No Widgets.
class MoveExecutor : public QObject
{
    Q_OBJECT
public:
    // owner: the holder of the machine's motion the moves are sent as (Machine::claimMotion).
    MoveExecutor(machine::Machine* machine, const QObject* owner, QObject* parent = nullptr);

    // Why positioning `move` cannot run at the fast speed: a feed move changed it on a
    // controller that can neither read it back nor knew it (the check refuses such programs
    // first; the adapter may have forgotten it since). Empty: it can.
    QString cannotPutBack(const RatedMove& move) const;
    // Runs `move`: the fast speeds put back (positioning) or its rates written (feed), then the
    // move. finished() at its end; at once (not ok, ErrorKind::Refused) when the machine
    // refuses the move. One at a time: a push while one runs is a programming error.
    void push(const RatedMove& move);
    // A reference run of the axes named (every axis when none): finished() at its end.
    void push(const Reference& reference);
    // Why the model cannot run a reference run (Capabilities' MotionMode::Reference); empty:
    // it can. The check asks it of every axis a G28 names, the machine refuses the same.
    static QString referenceRefusal(const Capabilities& caps, const QString& axis,
                                    const QString& controller);
    // Why the model cannot move `axis` relatively from an unknown position
    // (Capabilities::relativeNeedsPosition); empty: it can. The check asks it of a G91 move
    // of an axis whose position it does not know; the adapter refuses the same.
    static QString relativeRefusal(const Capabilities& caps, const QString& axis,
                                   const QString& controller);
    bool moveSent() const { return m_motion != 0; } // the machine moves for it now
    // The machine was stopped: the writes not yet acknowledged are not waited for (a move
    // already sent still reports its end).
    void dropPending();
    // Nothing more is reported (the run ended).
    void forget();
    // The fast speeds feed moves changed, and the interpolation a coordinated move turned on,
    // written back (a run's end): the requests, each with its controller id; none: nothing to
    // do. After a fault or an abort the caller need not wait for them.
    QMap<RequestId, QString> restore();

Q_SIGNALS:
    // The move arrived (ok), or why not: a write the controller refused (its kind, the message
    // naming the controller), a move the machine refused (Refused), a move that ended short or
    // failed (None: the failed request's kind came with the machine's requestFinished).
    void finished(bool ok, stepdeck::ErrorKind kind, const QString& message);

private:
    struct Controller
    {
        ParameterValue fast;  // read before the first feed write (perAxis empty: not read)
        RequestId read = 0;   // the read under way
        bool changed = false; // a feed move wrote a rate that positioning would also run at
        // Capabilities::interpolationParameter: written on by this executor (before: the value
        // the adapter knew, put back at the end; invalid: not known, left on).
        bool interpolationWritten = false;
        QVariant interpolationBefore;
    };
    QStringList controllersOf(const RatedMove& move) const;
    QMap<RequestId, QString> rateWrites(const RatedMove& move);
    QMap<RequestId, QString> putBack(const QStringList& controllers);
    // The interpolation write a coordinated move needs on controller `id` (none: the model has
    // no such parameter, fewer than two of its axes go together, or it is on already).
    ParameterSet interpolationWrite(const QString& id, const Capabilities& caps,
                                    const RatedMove& move, const ParameterSet& known);
    void sendMove();
    void onRequestFinished(const QString& controllerId, const CommandResult& result);
    void onMoveFinished(quint64 id, bool ok, const QString& message);
    void started(quint64 id, const QString& refusal);

    QPointer<machine::Machine> m_machine;
    const QObject* m_owner;
    QMap<QString, Controller> m_controllers;
    RatedMove m_move;           // the move pushed last
    bool m_pending = false;     // pushed, its writes not all acknowledged yet
    QSet<RequestId> m_requests; // those writes (and reads)
    quint64 m_motion = 0;       // Machine::move's or reference's id while it runs
};

} // namespace stepdeck::motion
