#include "CliEventWait.h"
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <climits>

namespace stepdeck::cli {

void CliEventWait::wake()
{
    if (m_loop)
        m_loop->quit();
}

bool CliEventWait::waitFor(const std::function<bool()>& done, int timeoutMs,
                           const bool& interrupted)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (interrupted)
            return false;
        const qint64 left = timeoutMs < 0 ? -1 : timeoutMs - clock.elapsed();
        if (timeoutMs >= 0 && left <= 0)
            return false;
        QEventLoop loop;
        QTimer deadline;
        deadline.setSingleShot(true);
        QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
        if (left > 0)
            deadline.start(int(qMin<qint64>(left, INT_MAX)));
        m_loop = &loop;
        loop.exec();
        m_loop = nullptr;
    }
    return true;
}

} // namespace stepdeck::cli
