// ServoLoop: the haptic thread. Calls a tick function at a fixed rate (1 kHz by
// default) with std::this_thread::sleep_until on a steady clock, until stop() or
// destruction. Deadlines advance by the period: a tick late by less than 20
// periods is made up (the rate holds on average); a longer stall restarts the
// schedule. Counts ticks and keeps the longest period seen.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

namespace sinew::haptics {

class ServoLoop {
 public:
  ServoLoop() = default;
  ServoLoop(const ServoLoop&) = delete;
  ServoLoop& operator=(const ServoLoop&) = delete;
  ~ServoLoop() { stop(); }

  // Starts the thread (stops a running one first). `tick` runs on the servo thread.
  void start(double rate_hz, std::function<void()> tick);
  // Asks the thread to finish and joins it; returns once no tick runs any more.
  void stop();
  bool running() const { return thread_.joinable(); }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_relaxed); }
  double max_period_ms() const { return max_period_ms_.load(std::memory_order_relaxed); }

 private:
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<double> max_period_ms_{0};
};

}  // namespace sinew::haptics
