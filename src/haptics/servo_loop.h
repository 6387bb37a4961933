// ServoLoop: the haptic thread. Calls a tick function at a fixed rate (1 kHz by
// default) with std::this_thread::sleep_until on a steady clock, until stop() or
// destruction. Deadlines advance by the period: a tick late by less than 20
// periods is made up (the rate holds on average); a longer stall restarts the
// schedule. The thread asks for real-time scheduling (SCHED_FIFO, as the
// OpenHaptics servo runs at the highest priority) and keeps its normal priority
// when the system refuses.
//
// Each tick's start time goes into a ring preallocated at start() (the last
// kRing ticks), so the period distribution can be read while or after the
// loop runs (period_stats) without the loop allocating or locking.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <thread>

namespace sinew::haptics {

// Periods between consecutive tick starts, in milliseconds.
struct PeriodStats {
  std::uint64_t updates = 0;  // ticks whose start lies in the window
  std::uint64_t periods = 0;  // periods measured (both ends in the window and in the ring)
  double p50 = 0, p99 = 0, max = 0, mean = 0;
};

class ServoLoop {
 public:
  static constexpr std::size_t kRing = std::size_t{1} << 16;  // 65 s at 1 kHz

  ServoLoop() = default;
  ServoLoop(const ServoLoop&) = delete;
  ServoLoop& operator=(const ServoLoop&) = delete;
  ~ServoLoop() { stop(); }

  // Starts the thread (stops a running one first). `tick` runs on the servo thread.
  void start(double rate_hz, std::function<void()> tick);
  // Asks the thread to finish and joins it; returns once no tick runs any more.
  void stop();
  bool running() const { return thread_.joinable(); }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_acquire); }
  double max_period_ms() const { return max_period_ms_.load(std::memory_order_relaxed); }
  // Whether the thread got real-time scheduling.
  bool realtime() const { return realtime_.load(std::memory_order_relaxed); }
  // Steady-clock time in nanoseconds (the clock of the tick stamps).
  static std::int64_t now_ns();
  // Distribution of the periods of the ticks that started in [from_ns, to_ns]
  // (steady-clock nanoseconds), from the ring (the last kRing ticks). Allocates
  // (call it from a report, not from the loop).
  PeriodStats period_stats(std::int64_t from_ns, std::int64_t to_ns) const;

 private:
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<double> max_period_ms_{0};
  std::atomic<bool> realtime_{false};
  std::unique_ptr<std::atomic<std::int64_t>[]> stamps_;  // tick start times, ring of kRing
};

}  // namespace sinew::haptics
