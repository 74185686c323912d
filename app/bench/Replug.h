#pragma once
#include "model/ModelInfo.h"
#include <QJsonObject>

namespace stepdeck::bench {

// stepdeck-bench --replug N: the peer vanishes N times in turn mid-poll, mid-jog, mid-stream
// (E-LAB <DC2> stream; a long move on models without one) and mid-write, and the time from
// the vanish to the host reporting the link gone is measured (in the thread a GUI runs in).
struct ReplugFigures
{
    QString model;
    int cycles = 0;
    QMap<QString, QList<double>> latencyMs; // by phase
    int notNoticed = 0;                     // link still "connected" 2 s after the vanish
    int reconnectFailures = 0;
    int axesMovingAfterReconnect = 0; // the device kept the last command (host was gone)
    double seconds = 0;

    QJsonObject toJson() const;
    QString toText() const;
};

ReplugFigures runReplug(const ModelInfo& model, int cycles, quint32 seed,
                        const std::function<void(const QString&)>& progress);

} // namespace stepdeck::bench
