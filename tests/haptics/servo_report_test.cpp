// The servo loop's tick stamps and the haptics report: the period distribution
// of a 1 kHz loop over a window, and the report line `sinew run --haptics-report`
// prints for a scene whose driver replays a trajectory.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "haptics/haptics_report.h"
#include "haptics/servo_loop.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::haptics;

TEST(ServoLoop, PeriodStatsOfAOneKilohertzLoop) {
  ServoLoop loop;
  std::atomic<int> ticks{0};
  loop.start(1000.0, [&] { ticks.fetch_add(1); });
  const std::int64_t from = ServoLoop::now_ns();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::int64_t to = ServoLoop::now_ns();
  loop.stop();
  const PeriodStats s = loop.period_stats(from, to);
  const double window_ms = static_cast<double>(to - from) * 1e-6;
  // Every tick that started in the window is counted, and consecutive ones give the periods.
  EXPECT_NEAR(static_cast<double>(s.updates), window_ms, 0.25 * window_ms);
  EXPECT_EQ(s.periods + 1, s.updates);
  // Deadlines advance by 1 ms: the mean period is 1 ms whatever the jitter.
  EXPECT_NEAR(s.mean, 1.0, 0.1);
  EXPECT_LE(s.p50, s.p99);
  EXPECT_LE(s.p99, s.max);
  EXPECT_GT(s.p50, 0.5);
  EXPECT_LT(s.p50, 1.5);
  // A window before the loop started holds nothing.
  EXPECT_EQ(loop.period_stats(0, from - 1'000'000'000).updates, 0u);
}

// As OpenHaptics' scheduler, loops of one rate share a servo thread: each cycle runs their
// ticks in the order they started. A loop that stops leaves the others running; a loop of
// another rate has its own thread.
TEST(ServoLoop, LoopsOfOneRateShareOneThread) {
  std::mutex m;
  std::vector<std::pair<int, std::thread::id>> calls;
  auto record = [&](int who) {
    std::lock_guard<std::mutex> lock(m);
    if (calls.size() < 100000) calls.emplace_back(who, std::this_thread::get_id());
  };
  ServoLoop a, b, c;
  a.start(1000.0, [&] { record(0); });
  b.start(1000.0, [&] { record(1); });
  c.start(500.0, [&] { record(2); });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  a.stop();
  EXPECT_FALSE(a.running());
  EXPECT_TRUE(b.running());
  const auto a_ticks = a.ticks();
  const auto b_ticks = b.ticks();
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(a.ticks(), a_ticks);  // stopped: never called again
  EXPECT_GT(b.ticks(), b_ticks + 5);
  b.stop();
  c.stop();
  std::lock_guard<std::mutex> lock(m);
  std::thread::id ta, tb, tc;
  int order_checked = 0;
  bool b_started = false;  // a ticks alone until b has joined its thread
  for (std::size_t i = 0; i < calls.size(); ++i) {
    const auto& [who, id] = calls[i];
    std::thread::id& seen = who == 0 ? ta : who == 1 ? tb : tc;
    if (seen == std::thread::id()) seen = id;
    EXPECT_EQ(seen, id) << who;  // one thread per loop throughout
    b_started = b_started || who == 1;
    if (who == 0 && b_started) {
      // In a cycle, b runs right after a on the same thread (c's ticks may fall in between).
      for (std::size_t j = i + 1; j < calls.size(); ++j) {
        if (calls[j].first == 2) continue;
        EXPECT_EQ(calls[j].first, 1);
        ++order_checked;
        break;
      }
    }
  }
  EXPECT_EQ(ta, tb);
  EXPECT_NE(ta, tc);
  EXPECT_GT(order_checked, 5);
}

TEST(HapticsReport, OneLinePerServedDriver) {
  test::TempDir dir;
  const std::string csv = dir.write("t.csv", "0 0 0 0 0 0 0 1 0\n1 1 0 0 0 0 0 1 0\n");
  auto sc = test::load("<Node name='root' dt='0.01'><GeomagicDriver name='drv' trajectory='" + csv +
                       "'/><GeomagicDriver name='idle'/></Node>");
  ASSERT_TRUE(sc.root);
  const std::int64_t from = ServoLoop::now_ns();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  for (int i = 0; i < 5; ++i) animate(*sc.root);
  const std::int64_t to = ServoLoop::now_ns();
  const std::string r = haptics_report(*sc.root, from, to);
  unsigned long long n = 0;
  double p50 = 0, p99 = 0, max = 0;
  ASSERT_EQ(std::sscanf(r.c_str(), "haptic loop: %llu updates, period p50 %lf ms, p99 %lf ms, max %lf ms", &n, &p50,
                        &p99, &max),
            4)
      << r;
  EXPECT_GT(n, 20u);
  EXPECT_LE(p50, p99);
  EXPECT_LE(p99, max);
  EXPECT_NE(r.find("drv"), std::string::npos) << r;
  EXPECT_EQ(r.find("idle"), std::string::npos) << "a driver without a device has no servo: " << r;
  auto none = test::load("<Node name='root'/>");
  EXPECT_EQ(haptics_report(*none.root, from, to).rfind("haptic loop: no device served", 0), 0u);
}
