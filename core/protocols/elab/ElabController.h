#pragma once
#include "ElabCtlJog.h"
#include "ElabCtlLine.h"
#include "ElabCtlMotionOps.h"
#include "ElabCtlParameters.h"
#include "ElabExchangeQueue.h"
#include "controller/Controller.h"
#include "controller/StatusPoller.h"
#include <QDeadlineTimer>
#include <QElapsedTimer>

namespace stepdeck::elab {

// The E-LAB 3-axis adapter (manual: elab-3axis-stepper-controller.de.txt) over a Transport.
// This class owns the link, polling, stop/panic/reset and parameters; the pieces:
//   ElabExchangeQueue   line discipline: one exchange in flight, replies in order, timeouts,
//                       <SYN> resync, at most one frame inside the transport, overtaking
//   ElabCtlLine         request sequences: status reads, ACK/NAK commands, pre-flight
//   ElabCtlStatusMapper status words -> MachineStatus, and the manual's refusal rules
//   ElabCtlMotionOps    moves, feed, <DC2> stream, reference, velocity; position bookkeeping
//   ElabCtlJog          <DC4> jog with coalescing
//   ElabCtlParameters   parameter validation and setup commands
//
// Decisions where the manual leaves room:
// - Standstill before a move, feed, reference, first velocity move or first jog: a pre-flight
//   reads RequestAxeState and RequestMachineState and refuses at once ("axes still moving")
//   instead of waiting; callers that want to wait (the CLI) poll the status themselves.
// - Moves finish on <ACK>; completion, limit hits and position corrections come from the
//   status reads that follow.
// - readParameters(): the board cannot read back; it returns the values this session last
//   wrote (said so in the message) or fails Unsupported for any never written. A reset, or a
//   connect that finds tmInvSetup, forgets them.
// - writeParameters(verify=true) succeeds on <ACK> and says it could not verify.
// - After the host's ForcePanicStop, status.panic stays set (and jog is refused) until a move,
//   feed, reference or velocity move is accepted, or after reset/reconnect. Moves are not
//   blocked by this latch, only by the board's own tmPanicStop.
// - Stop (STOP, close, link loss): <XOFF> ForceStopMove for moves, feeds and streams
//   ("stoppt sofort jegliche Bewegung mit Bremsrampen"), and <DC4> with zero rates whenever the
//   board may be in jog mode: the jog section lists only SetJogSpeed and ForcePanicStop, and
//   "Nullwerte stoppen den betreffenden Motor". STOP during a contour instead ends the stream
//   as a feed hold would (no further pair, EndOfFeed; the board runs out at most
//   ElabCtlMotionOps::kContourLeadSeconds of ticks), so every position stays known (issue 47);
//   close and link loss keep <XOFF>. See ElabControllerStop.cpp.
// - Polls while a stream runs (issue 47): at least ElabCtlMotionOps::kStreamPollsPerSecond a
//   second whatever the interval set, each deferred for a contour's reserve at most
//   kMaxPollDeferralMs; the contour's tick rate is capped (kContourMaxTickRate) so that the
//   wire leaves them their share.
// - A feed hold (issue 47 item 8) keeps the <DC2> stream open, and the board's RequestAxeState
//   reads feed mode (taXMove ...) until EndOfFeed: it cannot say that its axes stand. Once the
//   host sent nothing for longer than the ticks sent take at the tick rate (and a margin), the
//   stream's axes are shown standing at the host's count (ElabCtlMotionOps::showHeldAtRest),
//   moving again with the first pair after the hold.
// - Whenever a status read shows move or jog bits the host did not command (a lost jog ACK, a
//   motion from before this session), the host stops them and says so.
class ElabController : public Controller
{
    Q_OBJECT
public:
    ElabController(Transport* transport, const ControllerOptions& options,
                   QObject* parent = nullptr);
    ~ElabController() override;

    Capabilities capabilities() const override;
    ParameterSchema schema() const override;

    void openLink(RequestId id) override;
    void readParameters(RequestId id, const QStringList& names) override;
    void writeParameters(RequestId id, const ParameterSet& values, bool verify) override;
    void moveRelative(RequestId id, const AxisVector& steps) override;
    void feed(RequestId id, const AxisVector& steps) override;
    void feedStream(RequestId id, const QVector<AxisVector>& steps) override;
    void feedContour(RequestId id, std::shared_ptr<motion::ContourFeed> contour) override;
    void reference(RequestId id, const QMap<Axis, int>& directions) override;
    void velocityMove(RequestId id, const AxisVector& stepsPerS) override;
    void stop(RequestId id) override;
    void panic(RequestId id) override;
    void reset(RequestId id) override;
    void setSpindle(RequestId id, int rpm) override;
    void setCoolant(RequestId id, bool on) override;
    void setDrivePower(RequestId id, int percent) override;
    void refreshStatus(RequestId id) override;
    void sendRaw(RequestId id, const QByteArray& bytes) override;
    void setPollInterval(int ms) override;

    // Observation for tests and the bench.
    const ElabExchangeQueue& exchangeQueue() const { return m_queue; }
    const StatusPoller& poller() const { return m_poller; }

protected:
    void applyJogVelocity(const AxisVelocities& stepsPerS) override { m_jog.apply(stepsPerS); }
    QString jogRefusal() const override;
    QString jogAxisRefusal(Axis axis, double target) const override;
    void sendSafetyStop(std::function<void(bool)> done) override;
    void abortHostSide(ErrorKind kind, const QString& message) override;
    bool motionMayBeRunning() const override;

private:
    ElabCtlHooks hooks();
    bool requireLink(RequestId id);
    QString hostMotionRefusal() const; // non-empty while the host runs or tracks a motion
    // Limit switches and jog (ElabControllerStop.cpp): a limit that turns active under a
    // jogging or moving axis remembers the direction that reached it.
    void trackLimitSwitches();
    void onOpened();
    void startPoll();
    void cancelEverything(ErrorKind kind, const QString& message);
    void finishReset(RequestId id, quint64 epoch);
    // --- stop paths (ElabControllerStop.cpp) ---
    bool jogMayRun() const; // host jog, board jog mode, an unanswered <DC4>, jog bits
    // Writes the stop for whatever may move ahead of queued work. done(acknowledged, failure
    // kind, failure text): failure is Nak when the board refused a stop frame, else the error
    // of the exchange that got no answer. endFeed: flush the buffer and end the feed after the
    // board's ACK even when no stream runs on the host's side any more (a STOP during a
    // contour that fell back to it); a stream that runs always gets them.
    using StopDone = std::function<void(bool acknowledged, ErrorKind failure, const QString&)>;
    void writeStop(RequestId owner, StopDone done, bool endFeed = false);
    StopDone stopResult(RequestId id); // finishes a stop request by what writeStop heard
    void flushAndEndFeed(std::function<void()> then);
    // STOP during a contour (issue 47 item 3): the stream ends as a hold stops it, the stop is
    // finished once a status read shows the axes at rest.
    void stopContour(RequestId id);
    void awaitContourStandstill(quint64 epoch, QDeadlineTimer deadline);
    void contourStopFailed(const QString& why);
    void finishContourStops(bool standstill);
    // Polls while a stream runs (issue 47 item 4).
    void applyPollInterval();
    bool pollDeferralSpent();
    // A status read showed motion the host does not track: stop it and say so (once until
    // the board reports standstill again).
    void checkUntrackedMotion();
    void stopUntracked(const QString& why);
    void rememberWritten(const QString& name, const ParameterValue& value);
    void forgetWritten();
    void writeStep(const ElabCtlLine::Op& op, const QList<ElabParameterWrite>& plan, int index,
                   const QString& note);
    void writeAuxiliary(RequestId id, const QString& name, const QVariant& value,
                        const QByteArray& frame);

    ElabExchangeQueue m_queue;
    ElabCtlLine m_line;
    ElabCtlMotionOps m_ops{m_line};
    ElabCtlJog m_jog;
    StatusPoller m_poller{this};
    // The values this session last wrote (the board cannot read back), also published as
    // MachineStatus::knownParameters through rememberWritten / forgetWritten.
    ParameterSet m_written;
    bool m_pollDeferred = false; // a poll waits for a contour's reserve (startPoll)
    static constexpr int kDeferredPollMs = 5;
    // The longest a due poll waits for a contour's reserve: with the stream's interval of
    // 1000 / kStreamPollsPerSecond = 50 ms a poll starts at least every 75 ms (13/s).
    static constexpr int kMaxPollDeferralMs = 20;
    QElapsedTimer m_pollDeferredSince; // invalid: no poll waits
    int m_userPollMs = 50;             // the interval asked for (setPollInterval)
    QList<RequestId> m_contourStops;   // STOP requests waiting for a contour's end
    // Per running parameter write: the names already acknowledged, for the failure message.
    QHash<RequestId, QStringList> m_writeProgress;
    quint64 m_pollCount = 0;
    RequestId m_openId = 0;
    bool m_untrackedStopSent = false; // latched until a status read shows standstill
    QMap<Axis, int> m_limitApproach;  // axis -> direction (+1/-1) that ran into its active limit
};

} // namespace stepdeck::elab
