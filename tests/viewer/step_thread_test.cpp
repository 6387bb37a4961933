// The viewer's step thread: one step per start, on another thread, its result, duration and
// exceptions handed back by wait(), and the caller free while it runs.
#include "viewer/step_thread.h"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

namespace sinew::viewer {
namespace {

TEST(StepThread, RunsOneStepPerStartOnAnotherThreadAndReturnsItsResult) {
  std::atomic<int> calls = 0;
  std::thread::id where;
  StepThread t([&] {
    where = std::this_thread::get_id();
    return ++calls % 2 == 1;  // odd steps succeed
  });
  EXPECT_FALSE(t.busy());
  for (int k = 1; k <= 4; ++k) {
    t.start();
    EXPECT_TRUE(t.busy());
    double ms = -1;
    EXPECT_EQ(t.wait(&ms), k % 2 == 1);
    EXPECT_FALSE(t.busy());
    EXPECT_GE(ms, 0.0);
    EXPECT_EQ(calls, k);  // wait() returned after exactly this step
  }
  EXPECT_NE(where, std::this_thread::get_id());
}

TEST(StepThread, TheCallerRunsWhileTheStepRunsAndTheDurationIsTheSteps) {
  std::atomic<bool> release = false;
  StepThread t([&] {
    while (!release) std::this_thread::yield();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return true;
  });
  t.start();
  // The step waits for the caller: start() must not have waited for it.
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  release = true;
  double ms = 0;
  EXPECT_TRUE(t.wait(&ms));
  EXPECT_GE(ms, 20.0);   // the step's own sleep, measured on its thread
  EXPECT_LT(ms, 1000.0);
}

TEST(StepThread, WaitRethrowsWhatTheStepThrewAndTheThreadGoesOn) {
  int calls = 0;
  StepThread t([&]() -> bool {
    if (++calls == 1) throw std::runtime_error("singular matrix");
    return true;
  });
  t.start();
  try {
    t.wait(nullptr);
    FAIL() << "expected the step's exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "singular matrix");
  }
  EXPECT_FALSE(t.busy());
  t.start();
  EXPECT_TRUE(t.wait(nullptr));
  EXPECT_EQ(calls, 2);
}

TEST(StepThread, DestroyedWhileAStepRunsFinishesTheStepFirst) {
  std::atomic<bool> finished = false;
  {
    StepThread t([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      finished = true;
      return true;
    });
    t.start();
  }
  EXPECT_TRUE(finished);
}

}  // namespace
}  // namespace sinew::viewer
