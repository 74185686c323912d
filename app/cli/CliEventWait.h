#pragma once
#include <functional>

class QEventLoop;

namespace stepdeck::cli {

// The CLI's one way to wait (CliSession, CliMachineSession): runs the event loop until done(),
// a deadline or an interrupt; wake() makes a waiting loop check done() again at once.
class CliEventWait
{
public:
    // timeoutMs < 0: no deadline. False on timeout or while `interrupted` is set.
    bool waitFor(const std::function<bool()>& done, int timeoutMs, const bool& interrupted);
    void wake();

private:
    QEventLoop* m_loop = nullptr;
};

} // namespace stepdeck::cli
