#pragma once
#include "ElabCodec.h"

namespace stepdeck::elab {

// What a frame is answered with ("Aufbau der Befehle und Parameter": commands get <ACK>/<NAK>,
// requests repeat their control byte with the data; <SYN> and <DC2> get nothing).
// Ack: only <ACK> is an answer (ForcePanicStop: "Dieser antwortet mit einem <ACK>").
enum class Expect { None, Ack, AckNak, MachineState, AxeState, Temperature, RelPosition };
QString expectName(Expect expect);
// The reply a single command byte gets (for the console's raw frames).
Expect expectFor(const QByteArray& frame);
// Whether a reply of this kind answers a frame that expects `expect`.
bool expectMatches(Expect expect, Reply::Kind kind);

} // namespace stepdeck::elab
