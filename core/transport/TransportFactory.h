#pragma once
#include "Transport.h"

namespace stepdeck {

// "tcp://HOST:PORT" -> TcpTransport; anything else is a serial device path -> SerialTransport.
// ("sim" is resolved by ControllerSession, which pairs a LoopbackTransport with a simulator.)
Transport* createTransport(const QString& port, QObject* parent = nullptr);

} // namespace stepdeck
