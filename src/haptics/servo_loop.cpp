#include "haptics/servo_loop.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace sinew::haptics {

std::int64_t ServoLoop::now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// One servo thread and the loops it serves (all of the same period).
struct ServoThread {
  std::chrono::steady_clock::duration period{};
  std::mutex mutex;                // guards loops; held while a cycle runs the ticks
  std::vector<ServoLoop*> loops;   // in the order they started
  std::atomic<bool> stop{false};
  std::atomic<bool> realtime{false};
  std::thread thread;

  void run();
};

namespace {

// The servo threads by period (nanoseconds). Starting and stopping loops take this lock; the
// servo threads never do, so stop() may join one while holding it.
struct Registry {
  std::mutex mutex;
  std::map<std::int64_t, std::unique_ptr<ServoThread>> threads;
};

Registry& registry() {
  // Never destroyed: a loop stopped during static destruction still finds it.
  static Registry* r = new Registry;
  return *r;
}

// Sleeps until shortly before `deadline`, then spins to it. A sleeping thread wakes on a timer
// interrupt, which a virtual machine delivers late by tens of microseconds now and then; the
// spin absorbs that (it costs the servo's CPU a tenth of each period, the simulation runs on
// another). With no second CPU the thread only sleeps: spinning would take the simulation's.
// The CPUs counted are those the process may run on (its affinity), not the machine's.
bool second_cpu() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return CPU_COUNT(&set) > 1;
  return std::thread::hardware_concurrency() > 1;
}

void wait_until(std::chrono::steady_clock::time_point deadline, std::chrono::steady_clock::duration period) {
  using clock = std::chrono::steady_clock;
  static const bool spin = second_cpu();
  if (!spin) {
    std::this_thread::sleep_until(deadline);
    return;
  }
  std::this_thread::sleep_until(deadline - period / 8);
  while (clock::now() < deadline) {
  }
}

}  // namespace

void ServoThread::run() {
  // Real-time priority when allowed (a haptic servo's deadline is 1 ms); a refusal is normal
  // for an unprivileged user and leaves the thread as it was.
  sched_param sp{};
  sp.sched_priority = sched_get_priority_max(SCHED_FIFO);
  realtime.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0, std::memory_order_relaxed);
  const bool rt = realtime.load(std::memory_order_relaxed);
  using clock = std::chrono::steady_clock;
  auto next = clock::now();
  while (!stop.load(std::memory_order_acquire)) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      for (ServoLoop* loop : loops) loop->run_tick(ServoLoop::now_ns(), rt);
    }
    // Deadlines advance by the period: a short delay (the OS scheduling another thread)
    // is made up by the next cycles, so the rate holds on average; after a stall of more
    // than 20 periods the schedule restarts from now instead of bursting.
    next += period;
    const auto now = clock::now();
    if (now - next > 20 * period) next = now;
    wait_until(next, period);
  }
}

void ServoLoop::run_tick(std::int64_t start_ns, bool realtime) {
  const std::uint64_t k = ticks_.load(std::memory_order_relaxed);
  stamps_[k % kRing].store(start_ns, std::memory_order_relaxed);
  if (last_ns_ >= 0) {
    const double ms = static_cast<double>(start_ns - last_ns_) * 1e-6;
    if (ms > max_period_ms_.load(std::memory_order_relaxed)) max_period_ms_.store(ms, std::memory_order_relaxed);
  }
  last_ns_ = start_ns;
  realtime_.store(realtime, std::memory_order_relaxed);
  tick_();
  ticks_.store(k + 1, std::memory_order_release);
}

void ServoLoop::start(double rate_hz, std::function<void()> tick) {
  stop();
  ticks_.store(0);
  max_period_ms_.store(0);
  last_ns_ = -1;
  if (!stamps_) stamps_ = std::make_unique<std::atomic<std::int64_t>[]>(kRing);
  for (std::size_t i = 0; i < kRing; ++i) stamps_[i].store(0, std::memory_order_relaxed);
  tick_ = std::move(tick);
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / (rate_hz > 0 ? rate_hz : 1000.0)));
  const std::int64_t key = std::chrono::duration_cast<std::chrono::nanoseconds>(period).count();
  Registry& r = registry();
  std::lock_guard<std::mutex> reg(r.mutex);
  std::unique_ptr<ServoThread>& t = r.threads[key];
  if (!t) {
    t = std::make_unique<ServoThread>();
    t->period = period;
    t->loops.push_back(this);
    ServoThread* raw = t.get();
    t->thread = std::thread([raw] { raw->run(); });
  } else {
    std::lock_guard<std::mutex> lock(t->mutex);  // between two cycles
    t->loops.push_back(this);
  }
  running_ = true;
}

void ServoLoop::stop() {
  if (!running_) return;
  Registry& r = registry();
  std::lock_guard<std::mutex> reg(r.mutex);
  for (auto it = r.threads.begin(); it != r.threads.end(); ++it) {
    ServoThread& t = *it->second;
    bool last = false;
    {
      std::lock_guard<std::mutex> lock(t.mutex);  // no cycle runs: none of our ticks is under way
      auto found = std::find(t.loops.begin(), t.loops.end(), this);
      if (found == t.loops.end()) continue;
      t.loops.erase(found);
      last = t.loops.empty();
    }
    if (last) {
      t.stop.store(true, std::memory_order_release);
      t.thread.join();
      r.threads.erase(it);
    }
    break;
  }
  running_ = false;
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
