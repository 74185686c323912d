#pragma once
#include "ElabCtlLine.h"
#include "ElabCtlMotion.h"
#include "ElabCtlStream.h"
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QVector>
#include <optional>

namespace stepdeck::elab {

// The motion commands of the E-LAB adapter (manual sections "Befehle zur Positionierung",
// "Befehle im Arbeitsmodus", "Befehle zur einfachen Achsen Bewegung"): value checks against
// the wire types, the standstill pre-flight, the command, and the host-side position
// bookkeeping (ElabCtlMotion) from the status reads that follow. Also drives the <DC2> stream.
//
// - Moves pick the narrowest command: Z only <BS>, X/Y only <FF>, else <EOT>.
// - feed() with one axis: <RS>, then SetFeedSteps X/Y/Z. With several axes the single-axis
//   commands cannot run a line together, so it becomes a <DC2> stream of a straight line.
// - A repeated velocity move changes the rates without standstill (manual: the exception);
//   a direction reversal of a running axis is refused.
class ElabCtlMotionOps
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::elab::ElabCtlMotionOps)
public:
    explicit ElabCtlMotionOps(ElabCtlLine& line) : m_line(line) { m_clock.start(); }

    void moveRelative(RequestId id, const AxisVector& steps);
    void feed(RequestId id, const AxisVector& steps);
    void feedStream(RequestId id, const QVector<AxisVector>& steps);
    // A contour laid on ticks (issue 30): one <DC2> stream for as long as the contour gives
    // ticks, <CR> once it is closed and sent. The caller set the board's feed speeds to its
    // tick rate. wakeUp: posts pumpStream() to this adapter's thread (the contour calls it when
    // a move is given).
    void feedContour(RequestId id, std::shared_ptr<motion::ContourFeed> contour);
    // More of a contour may be there to send (ContourFeed's wake-up, on this thread).
    void pumpStream();
    void reference(RequestId id, const AxisVector& directions);
    void velocityMove(RequestId id, const AxisVector& stepsPerS);

    // Both status words were read: completion, limit hits, reference results, corrections.
    void onStatusRead();
    // ForceStopMove was answered: the running motion was cut short by the host.
    void onStopAccepted();
    void onFlowControl(bool resume);
    void abortStream(ErrorKind kind, const QString& message);
    void clear() { m_motion.clear(); }

    bool streaming() const { return m_stream.isActive(); }
    // A contour streams and what was sent runs less than kContourReserveSeconds ahead of the
    // board (counted from its first <DC2>, one tick per 1/rate): polls wait, so that the
    // stream's pairs keep ahead of the board (issue 30: no underrun while steps remain). Not
    // when it is that far behind: the contour waits for its next move and polls go on.
    static constexpr double kContourReserveSeconds = 0.04;
    bool contourNeedsWire() const;
    // At most this much of a contour's ticks go beyond the board (issue 30: a feed hold, which
    // stops giving ticks, takes effect within it whatever the board's buffer holds; issue 47:
    // so does STOP during a contour, stopContour()).
    static constexpr double kContourLeadSeconds = 0.2;

    // The wire's share of the status polls while a stream runs (issue 47 item 4). 57600 8N2
    // carries 57600 / 11 = 5 236 characters/s towards the board. A tick is one <DC2> pair (2
    // characters). A status read sends <HT> and <ENQ> (2 characters), and nothing else leaves
    // until both replies (<HT>BB#, <ENQ>BBBB#: 10 characters) are in: with the host's
    // turnaround about 16 character times of the line. kStreamPollsPerSecond is twice the 10/s
    // a moving machine must be read at, so a poll deferred for the board's reserve
    // (kContourReserveSeconds) or lost to noise still leaves 10/s.
    static constexpr double kWireCharsPerSecond = 57600.0 / 11;
    static constexpr int kStreamPollsPerSecond = 20;
    static constexpr double kPollWireChars = 16;
    // The highest tick rate of a contour (Capabilities::contourMaxTickRate, so the program
    // check's rate and note are this too): 2 100 ticks/s = 4 200 characters/s, 80 % of the
    // line; the polls take 320 characters/s; the rest (about 14 %) is what the chunks lose to
    // their pacing in whole milliseconds with at most one chunk on its way
    // (ElabExchangeQueue::kWireWindowBytes) and the headroom that rebuilds the board's reserve
    // after each poll. At 2 400 ticks/s (the cap before issue 47) the stream used the line to
    // its pacing's limit: its reserve never grew, and every poll waited for it.
    // (tst_elabcontourpty counts the polls at the simulator at this rate.)
    static constexpr double kContourMaxTickRate = 2100;
    static_assert(2 * kContourMaxTickRate + kStreamPollsPerSecond * kPollWireChars <=
                      0.87 * kWireCharsPerSecond,
                  "a contour's ticks must leave the status polls their share of the wire");

    // A contour streams (not a line or steps given whole).
    bool contourStreaming() const { return m_stream.isActive() && m_stream.contour(); }
    // STOP during a contour (issue 47 item 3), as a feed hold stops it: no further pair is
    // built, the chunk on its way leaves whole, and the stream ends with EndOfFeed. The board
    // runs the pairs it holds -- at most kContourLeadSeconds of ticks (one tick below 5
    // ticks/s) -- and stands; every pair it received is one the host counted, so every
    // position stays known. done(true): the EndOfFeed was acknowledged (standstill follows
    // within the lead); done(false): the stream ended otherwise (NAK, no reply, a limit
    // switch, panic, link loss) and the positions are what that path leaves.
    void stopContour(std::function<void(bool ended)> done);
    // A feed hold (issue 47 item 8): the contour is held, no chunk is on its way, and the
    // board has had the time to run every tick sent, kHeldRestMarginSeconds more included
    // (onStatusRead then shows the stream's axes standing, showHeldAtRest). The margin is the
    // last chunk's way to the board (a pair on the wire, a USB adapter's FIFO and its latency
    // timer, 16 ms by default) and the board's clock against the host's over the lead
    // (kContourLeadSeconds): two status polls of a stream (kStreamPollsPerSecond).
    static constexpr double kHeldRestMarginSeconds = 0.1;
    bool heldAtRest() const;
    // A motion the host started and has not yet seen end (any kind), a velocity axis that
    // still brakes after its rate 0 included.
    bool motionTracked() const { return m_motion.isActive() || !m_velocitySign.isEmpty(); }
    // The direction (+1/-1, 0: none) of the tracked motion on this axis.
    int direction(Axis axis) const
    {
        const qint64 v = m_motion.values().value(axis);
        return m_motion.kind() == ElabCtlMotion::Kind::Stream ? 0 : v > 0 ? 1 : v < 0 ? -1 : 0;
    }
    // Motion without an end of its own (velocity, reference searching its switch, a stream).
    bool openEnded() const
    {
        using K = ElabCtlMotion::Kind;
        return streaming() || ((m_motion.kind() == K::Velocity || m_motion.kind() == K::Reference ||
                                m_motion.kind() == K::Stream) &&
                               !m_motion.stopped());
    }
    // A velocity move the host has not stopped: its rates may change without standstill.
    bool velocityRunning() const
    {
        return m_motion.kind() == ElabCtlMotion::Kind::Velocity && !m_motion.stopped();
    }

private:
    void accepted(ElabCtlMotion::Kind kind, const AxisVector& values);
    void startStream(RequestId id, const QVector<AxisVector>& steps, const Triple<qint64>& line,
                     std::shared_ptr<motion::ContourFeed> contour = {});
    void endStream(RequestId id);
    void streamChanged(); // the hook, once a stream started or ended
    // A held contour at rest (heldAtRest): its axes shown standing; the first pair after the
    // hold shows them moving again.
    void showHeldAtRest();
    void showStreamMoving();
    void notifyContourStopped(bool ended);
    void correctPositions(const AxisVector& stopped);
    // Validated non-zero steps, or nullopt when the request is already finished.
    std::optional<AxisVector> stepsToSend(RequestId id, const AxisVector& steps);
    bool checkAxes(RequestId id, const AxisVector& values, qint64 minimum, qint64 maximum,
                   const QString& what);
    // Sends a VelocityMove once the axes in `reversing` report standstill (polled, bounded).
    void sendVelocity(RequestId id, const AxisVector& rates, bool running,
                      const QList<Axis>& reversing, qint64 deadlineMs, quint64 epoch);

    ElabCtlLine& m_line;
    // How far the contour's ticks sent run ahead of the board, in seconds; re-counted from now
    // when the board ran dry (a late move, a hold).
    double contourAhead();
    // The same without re-counting: < 0 when the board ran dry that long ago.
    double contourAheadNow() const;
    double contourLead(RequestId id);
    QElapsedTimer m_contourClock; // since the contour's first <DC2>, or since it ran dry
    qint64 m_contourBase = 0;     // the ticks sent when m_contourClock started
    bool m_leadWait = false;      // a pump waits for the board to run some of the lead
    bool m_restShown = false;     // a feed hold's axes are shown standing (showHeldAtRest)
    QList<std::function<void(bool)>> m_contourStopped; // stopContour() callers waiting
    ElabCtlMotion m_motion;
    ElabCtlStream m_stream;
    // Per axis the sign of the last non-zero velocity the board accepted, until a status read
    // shows that axis standing: "Eine Drehrichtungs Umkehr ist bei laufendem Motor hier nicht
    // möglich ... dann muss gewartet werden, bis diese Achse zum Stillstand gekommen ist".
    QMap<Axis, int> m_velocitySign;
    QElapsedTimer m_clock;
};

} // namespace stepdeck::elab
