#pragma once
#include "model/ModelInfo.h"
#include <QJsonObject>
#include <QMap>

namespace stepdeck::bench {

// The result of one model's soak (stepdeck-bench --soak N): the five figures that must be 0,
// then what happened on the way.
struct SoakFigures
{
    QString model;
    int commands = 0;
    quint32 seed = 0;
    // must be 0
    qint64 crashes = 0; // the soak process died (set by the parent, see main.cpp)
    qint64 hangs = 0;   // requests without a result within BenchHost::kRequestBoundMs
    // axes still moving 3 s after an orderly session end; for models without a stop command
    // (EMIS, laser axes) the same window, in which every target the soak sends is reached
    qint64 axesLeftMoving = 0;
    qint64 lostMoves = 0;       // host told success, device never started the move
    qint64 duplicatedMoves = 0; // device started one commanded move more than once
    // what happened
    qint64 sessions = 0;
    qint64 vanishes = 0;
    qint64 linkLosses = 0; // sessions that ended with the link lost without a vanish
    qint64 connectFailures = 0;
    qint64 movingAtReconnect = 0; // axes the device kept moving while its host was gone
    qint64 hostMovesOk = 0;       // per axis
    qint64 deviceMoves = 0;       // per axis
    qint64 unconfirmedMoves = 0;  // device started it, host was told it failed
    qint64 unmatchedDeviceMoves = 0;
    qint64 recoveries = 0;         // operator actions after refused moves (SoakProfile::recovery)
    qint64 jogMoves = 0;           // device moves made by jogs (EMIS, laser: target chunks)
    qint64 emergencyStops = 0;     // no stop command: axes still moving after a lost link
    qint64 axesMoved = 0;          // distinct device axes that started a move (a bus: drives)
    QMap<QString, qint64> faults;  // injected, by kind
    QMap<QString, qint64> results; // command results, by error kind
    double seconds = 0;

    bool clean() const
    {
        return crashes == 0 && hangs == 0 && axesLeftMoving == 0 && lostMoves == 0 &&
               duplicatedMoves == 0;
    }
    QJsonObject toJson() const;
    static SoakFigures fromJson(const QJsonObject& json);
    QString toText() const;
};

// Runs `commands` random commands against the model's simulator over a pseudo-terminal with
// ~1 % injected faults, as its ModelInfo::soak profile says; progress lines go to `progress`
// (may be empty). drives > 0 (a multi-drive model; --drives N): a bus of that many drives at
// addresses 1..N instead of the profile's (issue 32); the figures' model reads "nanotec/N".
SoakFigures runSoak(const ModelInfo& model, int commands, quint32 seed, int drives,
                    const std::function<void(const QString&)>& progress);

} // namespace stepdeck::bench
