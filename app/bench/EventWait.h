#pragma once
#include <functional>

namespace stepdeck::bench {

// Runs the event loop until done() or timeoutMs; false on timeout. Nothing sleeps: the loop
// wakes every few milliseconds to check done() again. The one wait of every bench host.
bool waitUntil(const std::function<bool()>& done, int timeoutMs);

} // namespace stepdeck::bench
