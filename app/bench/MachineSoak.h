#pragma once
#include "Soak.h"

namespace stepdeck::bench {

// stepdeck-bench --soak N --machine (issue 19): the fault soak over one machine of an E-LAB
// board (X, Y, Z) and a Nanotec drive (A), each its simulator on its own pseudo-terminal,
// driven only through core's Machine: moves of one or both controllers, jogs, STOP, status and
// parameter reads, with ~1 % faults on either link (dropped, corrupted, delayed replies,
// noise, a vanishing peer). The same five counts as the single-controller soak, summed over
// both devices; `model` is "machine".
SoakFigures runMachineSoak(int commands, quint32 seed,
                           const std::function<void(const QString&)>& progress);

} // namespace stepdeck::bench
