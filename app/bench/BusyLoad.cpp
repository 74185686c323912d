#include "BusyLoad.h"
#include <cstdint>

namespace stepdeck::bench {

namespace {
// A xorshift loop: pure ALU work the compiler cannot drop (its result is published), checked
// against the stop flag every few thousand rounds so stop() returns within microseconds.
void spin(const std::atomic<bool>& running, std::atomic<std::uint64_t>& sink)
{
    std::uint64_t x = 0x9e3779b97f4a7c15ULL;
    while (running.load(std::memory_order_relaxed)) {
        for (int i = 0; i < 4096; ++i) {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
        }
        sink.store(x, std::memory_order_relaxed);
    }
}

std::atomic<std::uint64_t> g_sink{0};
} // namespace

BusyLoad::BusyLoad(int threads)
{
    for (int i = 0; i < threads; ++i)
        m_threads.emplace_back([this] { spin(m_running, g_sink); });
}

BusyLoad::~BusyLoad()
{
    stop();
}

void BusyLoad::stop()
{
    m_running = false;
    for (std::thread& t : m_threads) {
        if (t.joinable())
            t.join();
    }
    m_threads.clear();
}

} // namespace stepdeck::bench
