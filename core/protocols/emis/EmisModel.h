#pragma once
#include "model/ModelInfo.h"

namespace stepdeck::emis {

// USB virtual COM port of the SMC-IC4 (chapter 9): 115200 baud, 8 data bits, 1 stop bit, no
// parity, no handshake. Software flow control must stay off: <DC1> and <DC3> (0x11, 0x13)
// are the arrival bytes of axes X and Z.
LineSettings lineSettings();
Capabilities capabilities();
ParameterSchema parameterSchema();
ModelInfo modelInfo();
// The simulator beyond the protocol: stepdeck-sim's machine options and the fault soak
// (EmisSimProfile.cpp).
ScenarioSupport scenarioSupport();
SoakProfile soakProfile();
// Input names and console notation for the UI (model/ModelPresentation.h).
ModelPresentation presentation();
// The note next to STOP/PANIC: the reset input (5.8) stops the board; what the host does after
// a reset. noStopNoteDetail(): the longer text for its tooltip.
QString noStopNote();
QString noStopNoteDetail();
// Console notation: printable text as it is, control bytes by their manual names
// ("<CR>", "<ACK>", "<NAK>", "<DC1>", "<BEL>", "<STX>", "<ETX>"), others as <xNN>.
QString formatTraffic(const QByteArray& bytes);
// The reverse for the console's send line; a line without a final <CR>, <STX> or <ETX> gets
// a <CR> (every command ends with it, chapter 9).
bool parseTraffic(const QString& text, QByteArray* bytes, QString* error);

} // namespace stepdeck::emis
