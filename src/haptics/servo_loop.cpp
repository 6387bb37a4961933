#include "haptics/servo_loop.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace sinew::haptics {

std::int64_t ServoLoop::now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void ServoLoop::start(double rate_hz, std::function<void()> tick) {
  stop();
  stop_.store(false);
  ticks_.store(0);
  max_period_ms_.store(0);
  if (!stamps_) stamps_ = std::make_unique<std::atomic<std::int64_t>[]>(kRing);
  for (std::size_t i = 0; i < kRing; ++i) stamps_[i].store(0, std::memory_order_relaxed);
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / (rate_hz > 0 ? rate_hz : 1000.0)));
  thread_ = std::thread([this, period, tick = std::move(tick)] {
    // Real-time priority when allowed (a haptic servo's deadline is 1 ms); a refusal is normal
    // for an unprivileged user and leaves the thread as it was.
    sched_param sp{};
    sp.sched_priority = sched_get_priority_max(SCHED_FIFO);
    realtime_.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0, std::memory_order_relaxed);
    using clock = std::chrono::steady_clock;
    auto next = clock::now();
    auto last = next;
    while (!stop_.load(std::memory_order_acquire)) {
      const auto start = clock::now();
      const std::uint64_t k = ticks_.load(std::memory_order_relaxed);
      stamps_[k % kRing].store(
          std::chrono::duration_cast<std::chrono::nanoseconds>(start.time_since_epoch()).count(),
          std::memory_order_relaxed);
      if (k > 0) {
        const double ms = std::chrono::duration<double, std::milli>(start - last).count();
        if (ms > max_period_ms_.load(std::memory_order_relaxed)) max_period_ms_.store(ms, std::memory_order_relaxed);
      }
      last = start;
      tick();
      ticks_.store(k + 1, std::memory_order_release);
      // Deadlines advance by the period: a short delay (the OS scheduling another thread)
      // is made up by the next ticks, so the rate holds on average; after a stall of more
      // than 20 periods the schedule restarts from now instead of bursting.
      next += period;
      const auto now = clock::now();
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

PeriodStats ServoLoop::period_stats(std::int64_t from_ns, std::int64_t to_ns) const {
  PeriodStats s;
  if (!stamps_) return s;
  const std::uint64_t n = ticks();
  // The newest entries may be rewritten while we read: skip a margin of the oldest ring slots.
  const std::uint64_t first = n > kRing - 64 ? n - (kRing - 64) : 0;
  std::vector<double> periods;
  periods.reserve(static_cast<std::size_t>(n - first));
  std::int64_t prev = -1;
  for (std::uint64_t k = first; k < n; ++k) {
    const std::int64_t t = stamps_[k % kRing].load(std::memory_order_relaxed);
    if (t < from_ns || t > to_ns) {
      prev = -1;
      continue;
    }
    ++s.updates;
    if (prev >= 0) periods.push_back(static_cast<double>(t - prev) * 1e-6);
    prev = t;
  }
  s.periods = periods.size();
  if (periods.empty()) return s;
  std::sort(periods.begin(), periods.end());
  auto quantile = [&](double q) {
    // Nearest rank: the smallest period with at least q of the periods at or below it.
    const std::size_t r = static_cast<std::size_t>(std::ceil(q * static_cast<double>(periods.size())));
    return periods[std::min(periods.size() - 1, r > 0 ? r - 1 : 0)];
  };
  s.p50 = quantile(0.5);
  s.p99 = quantile(0.99);
  s.max = periods.back();
  double sum = 0;
  for (double p : periods) sum += p;
  s.mean = sum / static_cast<double>(periods.size());
  return s;
}

}  // namespace sinew::haptics
