#pragma once
#include "EmisLink.h"
#include "EmisParameterPlan.h"
#include "EmisWorkSpeeds.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"

namespace stepdeck::emis {

// The EMIS SMC-IC4 adapter (manual: emis-smc-ic4-manual.de.txt, chapter 9) over a Transport.
//
// What the board cannot do shapes this class:
// - No stop command: stop() and panic() are refused (Unsupported, noStopCommandText()). Jog is a
//   chain of short relative vector moves, each covering at most kJogChunkSeconds of travel at the
//   commanded rate; the next chunk goes out only after the previous one's <DCn> arrived and only
//   while the jog lease holds, so a released jog ends with the chunk under way.
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
// - <BEL> means "refused, not executed" (an invalid value or a motor still moving); *PRSYS is
//   read as closed by <ACK> (the manual shows no closing byte; otherwise the read times out and
//   the stored values stay unknown); an absolute target where the axis stands is not sent (how
//   the board answers a move of no length, 9.11 does not say). docs/cli.md lists these.
class EmisController : public Controller
{
    Q_OBJECT
public:
    static constexpr double kJogChunkSeconds = 0.2;
    static constexpr int kStoreTimeoutMs = 3000; // per step of a flash write (##, programs)
    static constexpr int kSettleMs = 50;         // after opening, stale input is dropped

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
    void setReferenceDeadline(int ms) { m_referenceDeadlineMs = ms; }
    const EmisLink& link() const { return *m_link; }

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override;
    QString jogRefusal() const override;
    // The safety contract of the base (closeLink, loseLink, handleTransportFailure): there is
    // no stop to send, so the safety stop ends the jog chain and reports whether anything may
    // still move; abortHostSide() ends everything host-side through stopTrackingMotion().
    void sendSafetyStop(std::function<void(bool acknowledged)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;

private:
    struct Track
    {
        qint64 position = 0;     // sum of the arrived moves (known after a reference run)
        bool referenced = false; // in this session, and nothing lost since
        bool lost = false;       // a move's arrival never came: position unknown
        bool awaiting = false;   // <NAK> seen, <DCn> not yet
        bool overdue = false;    // awaiting past its deadline
        bool reference = false;  // the awaited motion is a reference run
        bool jogChunk = false;   // the awaited motion is a jog chunk
        // The host stopped waiting for this axis' arrival (deadline passed, link lost, no
        // reply to the move): it may still be moving. Cleared by its next <DCn>.
        bool unconfirmed = false;
        bool startPending = false;       // its move is on the line, <NAK> not yet seen
        bool arrivedBeforeStart = false; // <DCn> came while the <NAK> was still missing
        // Before an awaited arrival was declared lost: restored when it comes after all.
        bool lostBefore = false;
        bool referencedBefore = false;
        qint64 pendingSteps = 0; // relative distance of the awaited move
        qint64 deadlineMs = 0;
    };
    struct Known // working values as far as the host knows them (written, else stored)
    {
        QMap<Axis, qint64> startSpeed, runCurrent, idleCurrent; // work speed: m_speeds
        QMap<Axis, bool> switchNc;
        std::optional<qint64> ramp;
    };
    using Handler = EmisLink::Handler;

    // --- link and status (EmisController.cpp) ---
    void onOpened();
    void identify(int retries);
    void finishOpen(ErrorKind kind, const QString& message);
    void onPollDue();
    void applyInputs(const QList<bool>& levels);
    // What the host does when it stops tracking motion (link lost, closed; called by
    // abortHostSide()): there is no stop command to send, so it sends nothing; it stops the jog
    // chain, and every axis whose arrival is still awaited becomes unconfirmed with an unknown
    // position.
    void stopTrackingMotion(const QString& reason);
    void syncStatus();
    void publish();
    void changeLink(LinkState state, const QString& reason = {});
    bool requireLink(RequestId id);
    void request(const QByteArray& bytes, EmisLink::Expect expect, Handler done, int timeoutMs = 0,
                 int storedMotors = 0, bool exclusive = false);
    QString failureText(const QByteArray& bytes, const EmisLink::Result& r) const;
    ErrorKind failureKind(const EmisLink::Result& r) const;
    void finishFailure(RequestId id, const QByteArray& bytes, const EmisLink::Result& r);

    // --- motion (EmisCtlMotion.cpp) ---
    QString busyAxes(const QList<Axis>& axes, bool forReference) const;
    QString unknownAbsolute(const QList<VectorTarget>& targets) const; // refusal, or empty
    void startVector(RequestId id, const QList<VectorTarget>& targets, bool jog);
    void startHome(RequestId id, const QList<Axis>& axes, bool simultaneous);
    void onArrived(Axis axis);
    bool completeMotion(Axis axis); // the bookkeeping of an arrival; true for a jog chunk
    void checkDeadlines();
    void armDeadlineTimer();
    void markLost(Axis axis);
    void markOverdue(Axis axis);
    // The board may have been reset (5.8): its position counters start at 0 (absolute targets
    // mean something else, so no axis counts as referenced), its outputs are off and its work
    // speeds are the stored ones.
    void suspectReset();
    void settleStart(Axis axis, const EmisLink::Result& r, bool reference, bool jog, qint64 steps,
                     qint64 deadlineMs);
    qint64 moveDeadlineMs(const QList<VectorTarget>& targets) const;
    void updateMotionUnconfirmed();
    bool anyAwaiting() const;

    // --- jog (EmisCtlJog.cpp) ---
    void pumpJog();
    void sendJogChunk(QList<EmisWorkSpeeds::Write> speedWrites, QList<VectorTarget> chunk);
    bool jogHeld(Axis axis, double direction) const; // the input still asks for this way
    // A jog chunk ends at the soft limit; 0 and *why at the limit.
    qint64 clipToSoftLimit(Axis axis, qint64 steps, QString* why) const;
    void finishJogIfIdle();
    void haltJog(const QString& reason);

    // --- parameters (EmisCtlParameters.cpp) ---
    void runFrames(RequestId id, const QList<ParameterPlan::Frame>& frames, int index,
                   std::function<void()> onDone);
    void noteWritten(const ParameterSet& set);
    void noteStored(const SystemParameters& stored);
    void storeParameters(RequestId id, const QVariantMap& args);
    void readStoredParameters(RequestId id, Handler after = {});
    void clearStoredParameters(RequestId id);

    // --- operations (EmisCtlOperations.cpp) ---
    void setOutput(RequestId id, const QVariantMap& args);
    void referenceOperation(RequestId id, const QVariantMap& args);
    void writeInputProgram(RequestId id, const QVariantMap& args);
    void programStep(RequestId id, int input, const QList<QByteArray>& frames, int index);
    void abortProgram(RequestId id, int input, const QString& why, ErrorKind kind);
    void eraseInputProgram(RequestId id, const QVariantMap& args);

    EmisLink* m_link = nullptr;
    StatusPoller m_poller{this};
    QMap<Axis, Track> m_tracks;
    Known m_known;
    EmisWorkSpeeds m_speeds;
    ParameterSet m_written;    // working values written in this session
    SystemParameters m_stored; // the system parameters as last read or written
    QTimer m_deadlineTimer{this};
    QElapsedTimer m_clock;
    int m_referenceDeadlineMs = 120000;
    RequestId m_openId = 0;
    // While abortHostSide() cancels the link's requests, they finish with its kind and message.
    std::optional<QPair<ErrorKind, QString>> m_abort;
    int m_userPollMs = 50;
    bool m_programming = false;
    // jog
    AxisVelocities m_jogRates; // the newest rates from the ramp
    QString m_softLimitSaid;   // the last jog refusal for a soft limit (said once)
    bool m_jogSending = false; // a chunk (with its speed writes) is on its way
};

} // namespace stepdeck::emis
