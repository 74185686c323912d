#include "EventWait.h"
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

namespace stepdeck::bench {

namespace {
constexpr int kWakeMs = 2; // how often a wait re-checks its condition
}

bool waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() >= timeoutMs)
            return false;
        QEventLoop loop;
        QTimer::singleShot(kWakeMs, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

} // namespace stepdeck::bench
