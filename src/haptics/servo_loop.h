// ServoLoop: one device's servo callback, called at a fixed rate (1 kHz by default)
// until stop() or destruction. As OpenHaptics' scheduler, which runs the callbacks
// of every device in one servo thread, loops of the same rate share one thread:
// each cycle calls their ticks in the order they started. Two servo threads on
// two CPUs fare worse here: each waits on its own CPU's wake-ups, so one device
// or the other sees the late ones. The thread sleeps on a steady clock until an
// eighth of a period before each deadline and spins the rest (with a second
// CPU; a virtual machine wakes sleepers tens of microseconds late now and
// then: on this machine p99 of the period fell from 1.05–1.10 ms to
// 1.00–1.08 ms); deadlines advance by the
// period: a cycle late by less than 20 periods is made up (the rate holds on
// average); a longer stall restarts the schedule. The thread asks for real-time
// scheduling (SCHED_FIFO, as the OpenHaptics servo runs at the highest priority)
// and keeps its normal priority when the system refuses. It ends when its last
// loop stops.
//
// Each tick's start time goes into a ring preallocated at start() (the last
// kRing ticks), so the period distribution can be read while or after the
// loop runs (period_stats) without the loop allocating or locking.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

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

  // Starts calling `tick` on the servo thread of this rate (stops first when running).
  void start(double rate_hz, std::function<void()> tick);
  // Leaves the servo thread (joined when it was the last loop on it); returns once no tick of
  // this loop runs any more.
  void stop();
  bool running() const { return running_; }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_acquire); }
  double max_period_ms() const { return max_period_ms_.load(std::memory_order_relaxed); }
  // Whether the servo thread got real-time scheduling.
  bool realtime() const { return realtime_.load(std::memory_order_relaxed); }
  // Steady-clock time in nanoseconds (the clock of the tick stamps).
  static std::int64_t now_ns();
  // Distribution of the periods of the ticks that started in [from_ns, to_ns]
  // (steady-clock nanoseconds), from the ring (the last kRing ticks). Allocates
  // (call it from a report, not from the loop).
  PeriodStats period_stats(std::int64_t from_ns, std::int64_t to_ns) const;

 private:
  friend struct ServoThread;
  // On the servo thread: stamps the start, runs the tick, counts it.
  void run_tick(std::int64_t start_ns, bool realtime);

  std::function<void()> tick_;
  bool running_ = false;  // registered with a servo thread (changed under the registry lock)
  std::int64_t last_ns_ = -1;
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<double> max_period_ms_{0};
  std::atomic<bool> realtime_{false};
  std::unique_ptr<std::atomic<std::int64_t>[]> stamps_;  // tick start times, ring of kRing
};

}  // namespace sinew::haptics
