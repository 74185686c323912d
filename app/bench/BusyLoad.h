#pragma once
#include <atomic>
#include <thread>
#include <vector>

namespace stepdeck::bench {

// A reproducible CPU load beside a measurement (stepdeck-bench --load N, issue 21): N threads
// at normal priority, each spinning on integer arithmetic without sleeping or touching memory
// beyond a cache line, so N busy threads take N cores' worth of time slices from everything
// else on the machine for as long as they run. Stopped (and joined) by stop() or the
// destructor; nothing is left running after the measurement.
class BusyLoad
{
public:
    explicit BusyLoad(int threads);
    ~BusyLoad();
    BusyLoad(const BusyLoad&) = delete;
    BusyLoad& operator=(const BusyLoad&) = delete;

    void stop();
    int threads() const { return int(m_threads.size()); }

private:
    std::atomic<bool> m_running{true};
    std::vector<std::thread> m_threads;
};

} // namespace stepdeck::bench
