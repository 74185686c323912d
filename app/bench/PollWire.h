#pragma once
#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>
#include <atomic>
#include <optional>

namespace stepdeck::bench {

// The characters a paced wire carried, counted where the device sees them (BenchDevice, in the
// device thread; read from any thread). A request character that reaches the device while
// characters of a reply are still on the wire towards the host was sent while the other
// direction was busy (full duplex: the E-LAB's second status request crosses the first reply),
// so it is not on the poll's critical path. On a half-duplex bus (request, then reply) none is.
class WireCounter
{
public:
    struct Tally
    {
        qint64 requestChars = 0; // host -> device, delivered to the simulator
        qint64 replyChars = 0;   // device -> host, delivered to the host's terminal
        qint64 overlappedChars = 0;
        // Characters on the critical path: every reply character and every request character
        // that did not cross a reply. Exact while an overlapped request is no longer than the
        // reply it crosses (E-LAB: 1 character against 4).
        qint64 criticalChars() const { return requestChars + replyChars - overlappedChars; }
    };

    // The simulator handed n reply characters to the wire.
    void replyQueued(qsizetype n) { m_repliesQueued += n; }
    // n reply characters arrived at the host's end.
    void replyDelivered(qsizetype n) { m_repliesDelivered += n; }
    // One request character arrived at the device (called before the simulator reads it).
    void requestCharArrived();
    Tally tally() const;

private:
    std::atomic<qint64> m_requests{0};
    std::atomic<qint64> m_repliesQueued{0};
    std::atomic<qint64> m_repliesDelivered{0};
    std::atomic<qint64> m_overlapped{0};
};

// Status polls per second on the paced wire of one model and bus size, against what that wire
// allows: limitHz = 1 / (charsPerPoll x characterUs), charsPerPoll counted at the device over
// the measurement window (issue 21, item 1; docs/benchmark.md).
struct PollWireFigure
{
    QString key;    // "elab", "nanotec3", ...
    QString line;   // "19200 8N1"
    int drives = 0; // drives on the bus (multi-drive models), else 0
    double characterUs = 0;
    int polls = 0;                  // completed polls in the window
    std::optional<double> hz;       // achieved, first to last completion of the window
    std::optional<double> pollerHz; // the poller's own last report (completions in 1 s)
    std::optional<double> charsPerPoll;
    std::optional<double> limitHz;
    QString note; // why a figure is missing

    std::optional<double> ratio() const;
};

// Every model with a status poll: E-LAB; Nanotec with 1, 3, 4 and 8 drives on one bus; EMIS.
// windowMs: how long polls are counted after a second of warm-up.
constexpr int kPollWireWindowMs = 3000;
QList<PollWireFigure> measurePollWire(int windowMs);

QJsonObject pollWireJson(const QList<PollWireFigure>& figures);
QStringList pollWireText(const QList<PollWireFigure>& figures);

} // namespace stepdeck::bench
