#pragma once
#include "machine/MachineDescription.h"
#include "model/Capabilities.h"
#include "model/CommandResult.h"
#include "model/ParameterSchema.h"
#include "motion/CanonicalMove.h"
#include "motion/ContourSteps.h"
#include <QElapsedTimer>
#include <QList>
#include <QMap>
#include <QObject>
#include <QTimer>
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::motion {

class ContourFeed;

// A controller that runs contours as a step stream (Capabilities::contourStream: the E-LAB's
// <DC2>, manual "Schrittfolge"). Its slots are the controller's axes (slot = the Axis value,
// as Controller::feedContour counts them).
struct StepStream
{
    QString controller;
    StepScale scale;                      // a slot's steps per unit, < 0 on an inverted axis
    std::array<int, kMaxAxes> axisOfSlot; // machine axis index, -1: none
    // The controller axis of each slot: the controller's axes in their order
    // (Capabilities::axes), never the axis' value (issue 32).
    QList<Axis> slotAxes;
    double tickRate = 0; // ticks/s; 0: none can be chosen (tickRefusal says why)
    QString tickRefusal;
};

// The stream executor (issue 49 item 3, docs/architecture.md "One motion path"): a contour's
// canonical moves on a controller that takes them as a step stream, ContourSteps the one step
// generator. The stream's tick rate is written as the controller's feed-rate parameter on
// every axis (where the device does not hold it already), then the contour is given to the
// controller (ControllerSession::feedContour) and moves are appended while it runs (issue 30).
// At most kAheadSeconds of path wait beyond the ticks the controller took, so that a pause
// (close()) takes effect within that and the controller never waits for a move the program
// has. Reports each move's line as its ticks pass, and the end. No Widgets.
class StreamExecutor : public QObject
{
    Q_OBJECT
public:
    static constexpr double kAheadSeconds = 0.3;

    // The machine's step streams: one per controller with Capabilities::contourStream, its
    // slots laid onto the machine's axes, its tick rate from what the device holds (known).
    static std::vector<StepStream> streamsOf(const machine::MachineDescription& description,
                                             const QMap<QString, Capabilities>& capabilities,
                                             const QMap<QString, ParameterSchema>& schemas,
                                             const QMap<QString, ParameterSet>& known);
    // The tick rate a controller's stream runs at: the highest whole rate below
    // Capabilities::contourTickBelow on every axis and at most contourMaxTickRate, from what
    // the device is known to hold. 0 with *why when it cannot be chosen.
    static double tickRate(const Capabilities& caps, const ParameterSchema& schema,
                           const ParameterSet& known, QString* why);

    StreamExecutor(machine::Machine* machine, const StepStream& stream, QObject* parent = nullptr);
    ~StreamExecutor() override;

    // Starts at `current` (machine coordinates by axis index; an unknown axis from the
    // device's count): the tick rate, then the contour. Moves may be appended at once.
    void start(const std::vector<std::optional<double>>& current, double feedFactor = 1.0);
    // The feed override (0.1..kMaxFeedFactor) for the ticks not given yet: within
    // ElabCtlMotionOps::kContourLeadSeconds at the board.
    static constexpr double kMaxFeedFactor = 2.0;
    void setFeedFactor(double factor);
    // Appends a move (it must start at end()); empty, or why the stream refuses it.
    QString append(const CanonicalMove& move, const QString& text);
    // More may be appended now: the stream is open and less than kAheadSeconds wait.
    bool hasRoom() const;
    void close(); // no move follows: the stream ends after those appended
    // abort(): closed; a contour not given to the controller yet never is (finished at once,
    // not ok). One given ends by the controller's stop.
    void cancel();
    qint64 appended() const { return m_appended; }
    // Feed hold: no further tick is given until released (motion::ContourFeed::setHeld).
    void hold(bool held);
    bool isClosed() const { return m_closed; }
    const Position& end() const { return m_end; }
    const StepStream& stream() const { return m_stream; }
    int currentLine() const; // the move whose ticks are given now (0: none yet)
    int lastFinishedLine() const { return m_lastFinished; }

Q_SIGNALS:
    void blockStarted(int line, const QString& text);
    void blockFinished(int line);
    void roomForMoves();
    // The stream ended: every appended move ran (ok), or why not with the request's kind.
    void finished(bool ok, stepdeck::ErrorKind kind, const QString& message);

private:
    struct Block
    {
        int line = 0;
        QString text;
    };
    void giveContour();
    void onResult(const CommandResult& result);
    void onStreamDone(const CommandResult& result);
    void onSettleRead(const CommandResult& result);
    void watch(); // moves whose ticks passed; room for more
    void finish(bool ok, ErrorKind kind, const QString& message);

    machine::Machine* m_machine;
    StepStream m_stream;
    std::shared_ptr<ContourFeed> m_feed;
    Position m_end{};
    std::deque<Block> m_blocks; // appended, not reported finished; front: the one running
    qint64 m_reported = 0;      // moves reported finished
    qint64 m_appended = 0;
    int m_lastFinished = 0;
    RequestId m_tickWrite = 0;
    RequestId m_request = 0; // feedContour
    // After the stream ended (EndOfFeed taken), the board may still run the ticks it holds: a
    // status read shows when its axes are at rest; until then no move is done.
    RequestId m_settleRead = 0;
    QElapsedTimer m_settling;
    bool m_closed = false;
    bool m_ended = false;
    bool m_given = false; // feedContour was asked
    QTimer m_watch;
    QMetaObject::Connection m_results;
};

} // namespace stepdeck::motion
