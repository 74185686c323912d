#pragma once
#include "EmisLink.h"
#include "EmisWorkSpeeds.h"
#include <memory>

// The #E1 writes (9.5) that EmisWorkSpeeds asks for, sent on the link; what the board takes
// (or may not have taken) is noted in the bookkeeping. Used by EmisMotion (before each
// positioning move) and EmisJog (a chunk's speed, and the speed restored after a jog).
namespace stepdeck::emis {

// The first work speed write of a move that the board did not take: its bytes and reply.
using SpeedWriteFailure = std::optional<QPair<QByteArray, EmisLink::Result>>;

// One #E1; the board's speed is noted from the reply (unknown unless it was <ACK>ed), then
// `then` runs.
void writeWorkSpeed(EmisLink& link, EmisWorkSpeeds& speeds, const EmisWorkSpeeds::Write& write,
                    EmisLink::Handler then);
// The writes a positioning move of `axes` needs, queued now, so that nothing comes between them
// and the move queued next. The result holds the first one the board did not take; the move
// must then not go out (EmisLink::Request::cancelIf).
std::shared_ptr<SpeedWriteFailure> queueMoveSpeeds(EmisLink& link, EmisWorkSpeeds& speeds,
                                                   const QList<Axis>& axes);

} // namespace stepdeck::emis
