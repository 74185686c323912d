#pragma once
#include "EmisLink.h"
#include "EmisWorkSpeeds.h"
#include "controller/Controller.h"
#include <optional>

namespace stepdeck::emis {

// What the host knows of the board's working values (written in this session, else stored):
// the SMC-IC4 cannot report them (chapter 9). Shared by the pieces of the adapter.
struct EmisKnownValues
{
    QMap<Axis, qint64> startSpeed, runCurrent, idleCurrent;
    QMap<Axis, bool> switchNc;
    std::optional<qint64> ramp;
    // IP0/IP1 (9.12) as this session wrote it; no system entry holds it, so a reset (5.8)
    // forgets it (the board's power-on value is not documented).
    std::optional<bool> interpolation;
    EmisWorkSpeeds speeds; // the work speed, with what the board has (EmisWorkSpeeds)
};

// What the pieces of the SMC-IC4 adapter (EmisMotion, EmisJog, EmisParameters,
// EmisOperations) ask of the adapter itself: finishing requests, the normalised status and the
// base's jog input. EmisController implements it; the pieces never see the Controller's
// protected side otherwise.
class EmisHost
{
public:
    virtual ~EmisHost() = default;

    virtual Controller& controller() = 0;
    virtual const Controller& controller() const = 0;
    // Finishes id LinkDown ("not connected") unless the link is up.
    virtual bool requireLink(RequestId id) = 0;
    virtual void succeed(RequestId id, const QVariant& value = {}) = 0;
    virtual void fail(RequestId id, ErrorKind kind, const QString& message) = 0;
    // fail() with the kind and text of a link result for `bytes`.
    virtual void failExchange(RequestId id, const QByteArray& bytes, const EmisLink::Result& r) = 0;
    virtual MachineStatus& statusToChange() = 0;
    virtual void publish() = 0; // the bookkeeping into the status, then out
    // Every awaited arrival came: the board proved standstill (Controller).
    virtual void confirmStandstill() = 0;
    // The base's jog input (JogRamp): active, and stopped at once (all or one axis).
    virtual bool jogInputActive() const = 0;
    virtual void haltJogInput() = 0;
    virtual void haltJogInputAxis(Axis axis) = 0;
};

} // namespace stepdeck::emis
