#pragma once
#include "controller/ControllerSession.h"
#include "protocols/laser/LaserCodec.h"
#include <optional>

namespace stepdeck::bridge {

// One mapped laser axis of the bridge: what the laser wants of it (laser side, LaserBridge)
// and the controller request that serves it (controller side, LaserBridgeMotion).
struct LaserBridgeSlot
{
    struct Job
    {
        enum class Kind { None, Reference, Move };
        Kind kind = Kind::None;
        RequestId id = 0;          // the motion request
        RequestId confirmId = 0;   // the status read that confirms standstill
        bool accepted = false;     // the controller took it; waiting for standstill
        laser::CommandFrame frame; // the laser command it serves
        qint64 steps = 0;          // Move: target in controller steps
    };

    Axis laserAxis = Axis::X;
    Axis axis = Axis::X; // on the controller
    std::optional<laser::CommandFrame> wanted;
    Job job;
    bool referenced = false;
    bool waitingForIdle = false;
    std::optional<laser::StatusFrame> lastAnswer;
    QString failure;
};

} // namespace stepdeck::bridge
