#pragma once
#include "EmisExchange.h"
#include "EmisGrammar.h"
#include "EmisHost.h"
#include "EmisMotionTracker.h"
#include "EmisWorkSpeedWrites.h"

namespace stepdeck::emis {

// The motion commands of the SMC-IC4: vector moves (9.11) and reference runs (9.9), checked
// against what runs (the board would answer <BEL>) and what is known, each positioning move
// preceded by the work speed writes it needs (EmisWorkSpeeds). Their replies and arrivals go
// to EmisMotionTracker. Jog chunks are vector moves too; the jog chain (EmisJog) hears of them
// through Hooks.
class EmisMotion
{
    // Translations stay in the adapter's context (they were written there).
    Q_DECLARE_TR_FUNCTIONS(stepdeck::emis::EmisController)
public:
    struct Hooks
    {
        std::function<bool(Axis)> jogging; // the axis has a jog rate
        // A jog chunk's move was taken (ok) or not (why).
        std::function<void(bool ok, const QString& why)> chunkSettled;
    };

    EmisMotion(EmisHost& host, EmisExchange& exchange, EmisKnownValues& known,
               EmisMotionTracker& tracker, Hooks hooks);

    void moveRelative(RequestId id, const AxisVector& steps);
    void moveAbsolute(RequestId id, const AxisVector& targets);
    void reference(RequestId id, const QMap<Axis, int>& directions);
    // A vector move (a jog chunk: jog, id 0) and a reference run, checked against what runs.
    void startVector(RequestId id, const QList<VectorTarget>& targets, bool jog);
    void startHome(RequestId id, const QList<Axis>& axes, bool simultaneous);
    QString unknownAbsolute(const QList<VectorTarget>& targets) const; // refusal, or empty

private:
    QString busyAxes(const QList<Axis>& axes, bool forReference) const;
    void onVectorStarted(RequestId id, const QList<VectorTarget>& targets, bool jog,
                         qint64 deadline, const QByteArray& bytes,
                         const std::shared_ptr<SpeedWriteFailure>& failed,
                         const EmisLink::Result& r);
    qint64 moveDeadlineMs(const QList<VectorTarget>& targets) const;

    EmisHost& m_host;
    EmisExchange& m_exchange;
    EmisKnownValues& m_known;
    EmisMotionTracker& m_tracker;
    Hooks m_hooks;
};

} // namespace stepdeck::emis
