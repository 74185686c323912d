#pragma once
#include "ArcPath.h"
#include "ContourMoves.h"
#include "model/CommandResult.h"
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <deque>
#include <memory>

namespace stepdeck::motion {
class ContourFeed;
}
namespace stepdeck::machine {
class Machine;
}

namespace stepdeck::program {

// One contour of a running program on a controller that takes it as a step stream (issue 30,
// ContourMoves): the stream's tick rate is written as the controller's feed-rate parameter on
// every axis (where the device does not hold it already), then the contour is given to the
// controller (ControllerSession::feedContour) and the program's feed moves are appended while
// it runs. At most kAheadSeconds of path wait beyond the ticks the controller took, so that a
// pause (close()) takes effect within that and the controller never waits for a move the
// program has. Reports each block as its ticks pass, and its end. No Widgets.
class ContourRun : public QObject
{
    Q_OBJECT
public:
    static constexpr double kAheadSeconds = 0.3;

    ContourRun(machine::Machine* machine, const ContourMoves::Stream& stream,
               QObject* parent = nullptr);
    ~ContourRun() override;

    // Starts at `current` (the program's current point; an unknown axis from the device's
    // count): the tick rate, then the contour. Moves may be appended at once.
    void start(const AxisPositions& current, double feedFactor = 1.0);
    // The feed override (0.1..kMaxFeedFactor) for the ticks not given yet: within
    // ElabCtlMotionOps::kContourLeadSeconds at the board.
    static constexpr double kMaxFeedFactor = 2.0;
    void setFeedFactor(double factor);
    // Appends a block's move (it must start at end()); empty, or why the stream refuses it.
    QString append(const motion::CanonicalMove& move, const QString& text);
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
    const motion::Position& end() const { return m_end; }
    const ContourMoves::Stream& stream() const { return m_stream; }
    int currentLine() const; // the block whose ticks are given now (0: none yet)
    int lastFinishedLine() const { return m_lastFinished; }

Q_SIGNALS:
    void blockStarted(int line, const QString& text);
    void blockFinished(int line);
    void roomForMoves();
    // The stream ended: every appended block ran (ok), or why not with the request's kind.
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
    void watch(); // blocks whose ticks passed; room for more
    void finish(bool ok, ErrorKind kind, const QString& message);

    machine::Machine* m_machine;
    ContourMoves::Stream m_stream;
    std::shared_ptr<motion::ContourFeed> m_feed;
    motion::Position m_end{};
    std::deque<Block> m_blocks; // appended, not reported finished; front: the one running
    qint64 m_reported = 0;      // moves reported finished
    qint64 m_appended = 0;
    int m_lastFinished = 0;
    RequestId m_tickWrite = 0;
    RequestId m_request = 0; // feedContour
    // After the stream ended (EndOfFeed taken), the board may still run the ticks it holds: a
    // status read shows when its axes are at rest; until then no block is done.
    RequestId m_settleRead = 0;
    QElapsedTimer m_settling;
    bool m_closed = false;
    bool m_ended = false;
    bool m_given = false; // feedContour was asked
    QTimer m_watch;
    QMetaObject::Connection m_results;
};

} // namespace stepdeck::program
