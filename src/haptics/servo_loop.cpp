#include "haptics/servo_loop.h"

#include <chrono>

namespace sinew::haptics {

void ServoLoop::start(double rate_hz, std::function<void()> tick) {
  stop();
  stop_.store(false);
  ticks_.store(0);
  max_period_ms_.store(0);
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / (rate_hz > 0 ? rate_hz : 1000.0)));
  thread_ = std::thread([this, period, tick = std::move(tick)] {
    using clock = std::chrono::steady_clock;
    auto next = clock::now();
    auto last = next;
    while (!stop_.load(std::memory_order_acquire)) {
      tick();
      const auto now = clock::now();
      if (ticks_.load(std::memory_order_relaxed) > 0) {
        const double ms = std::chrono::duration<double, std::milli>(now - last).count();
        if (ms > max_period_ms_.load(std::memory_order_relaxed)) max_period_ms_.store(ms, std::memory_order_relaxed);
      }
      last = now;
      ticks_.fetch_add(1, std::memory_order_relaxed);
      // Deadlines advance by the period: a short delay (the OS scheduling another thread)
      // is made up by the next ticks, so the rate holds on average; after a stall of more
      // than 20 periods the schedule restarts from now instead of bursting.
      next += period;
      if (now - next > 20 * period) next = now;
      std::this_thread::sleep_until(next);
    }
  });
}

void ServoLoop::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true, std::memory_order_release);
  thread_.join();
}

}  // namespace sinew::haptics
