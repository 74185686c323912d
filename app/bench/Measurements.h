#pragma once
#include "model/ParameterSchema.h"
#include <QJsonValue>
#include <QList>
#include <QString>
#include <optional>

namespace stepdeck {
struct ModelInfo;
}

namespace stepdeck::bench {

constexpr int kPollIntervalMs = 1;  // the StatusPoller's floor: polls back to back
constexpr int kPollWindowMs = 2600; // the poller reports its rate over the last second
constexpr int kPanicRepetitions = 20;
// Under load the tail is the point: with 100 runs p99 is the second slowest, not the slowest.
constexpr int kPanicUnderLoadRepetitions = 100;
constexpr int kFeedStreamSteps = 100000;
constexpr int kFeedBudgetMs = 3000;

struct Figure
{
    std::optional<double> value;
    QString note; // why there is no value, or what limited it
};

struct LatencyFigure
{
    std::optional<double> medianMs;
    std::optional<double> p99Ms;
    int samples = 0;
    int pausedByXoff = 0;        // runs in which the controller had paused the host with XOFF
    bool deviceRealtime = false; // every run's simulator thread ran SCHED_FIFO
    QString note;
};

// What the device wants written before it moves (ModelInfo::setupBeforeMotion), at the schema
// defaults: the E-LAB simulator powers on with setup incomplete and refuses a feed stream or a
// jog until its ramp and feed parameters are written. Empty for models that need nothing.
ParameterSet setupParameters(const ModelInfo& model);

// A figure for the --json output: rounded to `decimals`, null when there is none.
QJsonValue roundedJson(const std::optional<double>& value, int decimals);

// Nearest-rank percentile (fraction 0..1) and median of latency samples, in their unit.
double percentile(QList<double> samples, double fraction);
double median(QList<double> samples);

// Achieved status polls per second of the adapter against the simulator on a pty.
Figure measurePollRate(const ModelInfo& model, bool paced);
// Call of ControllerSession::panic() -> panic byte seen by the simulator, while a
// kFeedStreamSteps-step DC2 stream is queued behind the controller's XOFF.
// With deviceRealtime the simulator's thread asks for SCHED_FIFO (BenchDevice::Config).
LatencyFigure measurePanicLatency(const ModelInfo& model, int repetitions, bool deviceRealtime);
// DC2 single steps delivered to the simulator per second.
Figure measureFeedThroughput(const ModelInfo& model, bool paced);

} // namespace stepdeck::bench
