#pragma once
#include "EmisExchange.h"
#include "EmisHost.h"
#include "EmisJog.h"
#include "EmisMotion.h"
#include "EmisMotionTracker.h"
#include "EmisOperations.h"
#include "EmisParameters.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"

namespace stepdeck::emis {

// The EMIS SMC-IC4 adapter (manual: emis-smc-ic4-manual.de.txt, chapter 9) over a Transport.
// This class owns the link, the connect sequence, input polling, the status and the safety
// contract of the base; the pieces, each with one responsibility:
//   EmisLink           line discipline: one command at a time, its reply, timeouts, <DCn>
//   EmisExchange       requests onto the link and what their failures mean
//   EmisMotion         vector moves and reference runs: checked, work speeds set, sent
//   EmisMotionTracker  their arrivals and deadlines, the position bookkeeping
//   EmisJog            the jog as a chain of short vector moves
//   EmisParameters     working values (set) and system parameters (##, *PRSYS, *PESYS)
//   EmisOperations     model operations (outputs, input programs) and the console
//   EmisWorkSpeeds     the work speed (#E1) the board has and the one moves run at
// The pieces reach the adapter only through EmisHost (private base) and share what the host
// knows of the board's working values (EmisKnownValues).
//
// What the board cannot do shapes this class:
// - No stop command: stop() and panic() are refused (Unsupported, noStopCommandText()). Jog is a
//   chain of short relative vector moves, each covering at most EmisJog::kJogChunkSeconds of
//   travel at the commanded rate; the next chunk goes out only after the previous one's <DCn>
//   arrived and only while the jog lease holds, so a released jog ends with the chunk under way.
// - No position or status query: positions are bookkeeping from completed moves (the sum of the
//   arrived relative moves since connecting; absolute, i.e. known, after a reference run in this
//   session). "Moving" is the time between <NAK> and <DCn>. A <DCn> that does not come within its
//   deadline, or a link lost while moves run, sets MachineStatus::motionUnconfirmed and makes the
//   axis' position unknown until it is referenced again.
// - The poller reads the inputs (@IG); inputs 1-4 are the reference switches (normally open
//   unless reference-switch-type says NC). Polls without an answer (silence, garbage) mean link
//   lost; a <BEL> is an answer.
// - The reset input (5.8) is what stops the board. A request without an answer or an arrival
//   that never comes may be a reset: every axis then counts as not referenced, the outputs as
//   unknown, the work speeds as forgotten (suspectReset()).
//
// modelOperation() names (args -> result value):
//   "set-output"              {output 1..7, on}                      A<n>,<0|1> (9.3)
//   "reference"               {axes "XYZU", simultaneous=false}      $H... (9.9)
//   "store-parameters"        {parameters: ParameterSet, skipUnstorable=false} -> {commands,
//                             skipped}                              "##" writes (9.14)
//   "read-stored-parameters"  {} -> {parameters: ParameterSet, entries: [text], notes: [text]}
//   "clear-stored-parameters" {}                                     *PESYS (9.16)
//   "write-input-program"     {input 1..8, title, commands: [text], force=false} (9.17)
//   "erase-input-program"     {input 1..8}                           *PEIN<n> (9.18)
//
// Decisions where the manual leaves room:
// - reference(): the board picks the direction of its reference run; 1 selects an axis, 0
//   leaves it out, -1 is refused (InvalidValue). Axes run one after the other unless the
//   "reference" operation asks for simultaneous runs.
// - Moves, reference runs and parameter writes finish when the board accepted them (<NAK> or
//   <ACK>); arrival is status (moving, positions).
// - readParameters() returns the working values written in this session (the board cannot
//   report them); the stored values come from "read-stored-parameters" (*PRSYS).
// - A jog runs each chunk at the commanded rate by setting the axis' work speed (#E1). Every
//   positioning move first sets the work speed of each of its axes the board is not known to
//   have (EmisWorkSpeeds: written in this session, else stored, else 1000), so no move runs at
//   a jog rate left on the board; when a jog ends the work speed is set back the same way.
// - <BEL> means "refused, not executed" (an invalid value or a motor still moving); an @IG
//   status read answered with <BEL> while a motion of the host's runs is answered by that
//   motion and the inputs' last levels, like a poll (busyMoving()); *PRSYS is read as closed
//   by <ACK> (the manual shows no closing byte; otherwise the read times out and the stored
//   values stay unknown); an absolute target where the axis stands is not sent (how the board
//   answers a move of no length, 9.11 does not say). docs/cli.md lists these.
class EmisController : public Controller, private EmisHost
{
    Q_OBJECT
public:
    static constexpr int kSettleMs = 50; // after opening, stale input is dropped

    EmisController(Transport* transport, const ControllerOptions& options,
                   QObject* parent = nullptr);
    ~EmisController() override;

    Capabilities capabilities() const override;
    ParameterSchema schema() const override;

    void openLink(RequestId id) override;
    void readParameters(RequestId id, const QStringList& names) override;
    void writeParameters(RequestId id, const ParameterSet& values, bool verify) override;
    void moveRelative(RequestId id, const AxisVector& steps) override;
    void moveAbsolute(RequestId id, const AxisVector& targets) override;
    void reference(RequestId id, const QMap<Axis, int>& directions) override;
    void stop(RequestId id) override { refuseNoStopCommand(id); }
    void panic(RequestId id) override { refuseNoStopCommand(id); }
    void refreshStatus(RequestId id) override;
    void sendRaw(RequestId id, const QByteArray& bytes) override;
    void setPollInterval(int ms) override;
    void modelOperation(RequestId id, const QString& name, const QVariantMap& args) override;

    // For tests: how long a reference run may take before its arrival counts as lost.
    void setReferenceDeadline(int ms) { m_tracker.setReferenceDeadline(ms); }
    const EmisLink& link() const { return m_exchange.link(); }

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override { m_jog.apply(stepsPerS); }
    QString jogRefusal() const override;
    // The safety contract of the base (closeLink, loseLink, handleTransportFailure): there is
    // no stop to send, so the safety stop ends the jog chain and reports whether anything may
    // still move; abortHostSide() ends everything host-side through stopTrackingMotion().
    void sendSafetyStop(std::function<void(bool acknowledged)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;

private:
    // --- EmisHost: what the pieces ask of the adapter ---
    Controller& controller() override { return *this; }
    const Controller& controller() const override { return *this; }
    bool requireLink(RequestId id) override;
    void succeed(RequestId id, const QVariant& value) override { finishOk(id, value); }
    void fail(RequestId id, ErrorKind kind, const QString& message) override
    {
        finishError(id, kind, message);
    }
    void failExchange(RequestId id, const QByteArray& bytes, const EmisLink::Result& r) override;
    MachineStatus& statusToChange() override { return mutableStatus(); }
    void publish() override;
    void confirmStandstill() override { noteStandstillConfirmed(); }
    bool jogInputActive() const override { return jogActive(); }
    void haltJogInput() override { haltJogImmediately(); }
    void haltJogInputAxis(Axis axis) override { haltJogAxis(axis); }

    // --- link and status ---
    void onOpened();
    void identify(int retries);
    void finishOpen(ErrorKind kind, const QString& message);
    void onPollDue();
    void applyInputs(const QList<bool>& levels);
    // An @IG answered with <BEL> while a motion of the host's is under way (chapter 9).
    bool busyMoving(const EmisLink::Result& r) const;
    // What the host does when it stops tracking motion (link lost, closed; called by
    // abortHostSide()): there is no stop command to send, so it sends nothing; it stops the jog
    // chain, and every axis whose arrival is still awaited becomes unconfirmed with an unknown
    // position.
    void stopTrackingMotion(const QString& reason);
    void syncStatus();
    void changeLink(LinkState state, const QString& reason = {});
    EmisMotionTracker::Hooks trackerHooks();
    EmisMotion::Hooks motionHooks();

    EmisExchange m_exchange;
    EmisKnownValues m_known;
    EmisMotionTracker m_tracker;
    EmisMotion m_motion;
    EmisJog m_jog;
    EmisParameters m_parameters;
    EmisOperations m_operations;
    StatusPoller m_poller{this};
    RequestId m_openId = 0;
    int m_userPollMs = 50;
};

} // namespace stepdeck::emis
