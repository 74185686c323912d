#pragma once
#include "bridge/LaserAnswerPolicy.h"
#include "bridge/LaserBridgeConfig.h"
#include "bridge/LaserBridgeLog.h"
#include "bridge/LaserBridgeSlot.h"
#include <QCoreApplication>
#include <QPointer>
#include <functional>

namespace stepdeck::bridge {

// The controller side of the laser bridge: reference and move requests through the session,
// standstill confirmed by a status read, retargeting by stop where the controller allows it,
// and what the controller's results mean for the laser's targets (answered through the laser
// side, LaserBridge, by Hooks). Knows no laser bytes.
class LaserBridgeMotion
{
    // Translations stay in the bridge's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::bridge::LaserBridge)
public:
    using Slot = LaserBridgeSlot;
    using Job = LaserBridgeSlot::Job;
    struct Hooks // the laser side
    {
        std::function<void(Slot&, const LaserAnswer&)> reply; // the frame, else drop
        std::function<void(Slot&, const QString& why)> drop;  // no answer, with the reason
        std::function<void(const Slot&)> publish;
        std::function<void(LaserBridgeLogEntry::Kind, const QString&)> log;
        std::function<void()> stopEnded; // a stop ended (door report waiting for it)
        std::function<void()> finishShutdown;
        std::function<bool()> doorOpen;
        std::function<bool()> shuttingDown;
    };

    LaserBridgeMotion(ControllerSession* session, const LaserBridgeConfig& config,
                      const Capabilities& caps, const LaserAnswerPolicy& answers,
                      QMap<Axis, Slot>& axisSlots, Hooks hooks);

    void dispatch(Slot& slot);
    void retarget(Slot& slot); // a new target while the slot's job runs
    // Stops the jobs under way (where the controller has a stop), for a retarget or the door.
    void requestStop();
    // The shutdown's stop: sent at once, its result ends the shutdown.
    void stopForShutdown();
    void clearStop() { m_stop = StopStage::None; }
    bool stopping() const { return m_stop != StopStage::None; }
    void redispatchAll();
    void dropTargetsOfLostLink();

    // ControllerSession signals.
    void onResult(const CommandResult& result);
    void onStatus();
    void onLinkState(LinkState state, bool serving);

private:
    enum class StopStage { None, Requested, Settling, Confirming };

    void startReference(Slot& slot);
    void startMove(Slot& slot);
    bool canStopToRetarget() const;
    void checkStandstill(Slot& slot);
    void conclude(Slot& slot);
    void onRefused(Slot& slot, const CommandResult& result);
    void onStopResult(const CommandResult& result);
    void advanceStop();
    bool controllerIdle() const;
    bool referencedNow(const Slot& slot) const;
    Slot* slotForRequest(RequestId id);
    void log(LaserBridgeLogEntry::Kind kind, const QString& text) { m_hooks.log(kind, text); }

    QPointer<ControllerSession> m_session;
    const LaserBridgeConfig& m_config;
    const Capabilities& m_caps; // the bridge reads them at start()
    const LaserAnswerPolicy& m_answers;
    QMap<Axis, Slot>& m_slots;
    Hooks m_hooks;
    StopStage m_stop = StopStage::None;
    RequestId m_stopId = 0;
    RequestId m_stopConfirmId = 0;
};

} // namespace stepdeck::bridge
