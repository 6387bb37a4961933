// State metric and reading schedule (regression-protocol.md §5, §6).
#include "regression/state_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "regression/number_format.h"

namespace sinew::regression {
namespace {

StateBlock make_block(double time, std::vector<double> x, std::vector<double> v = {}) {
  StateBlock block;
  block.time = time;
  block.lines.push_back({'X', std::move(x)});
  if (!v.empty()) block.lines.push_back({'V', std::move(v)});
  return block;
}

TEST(MeanAbsDifference, AveragesOverCommonPrefix) {
  const std::vector<double> ref = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(mean_abs_difference(ref, std::vector<double>{1, 2.5, 2, 4}), 1.5 / 4);
  // Size mismatch: only the common prefix counts.
  EXPECT_DOUBLE_EQ(mean_abs_difference(ref, std::vector<double>{0, 2}), 1.0 / 2);
  EXPECT_DOUBLE_EQ(mean_abs_difference(std::vector<double>{1}, std::vector<double>{3, 9, 9}), 2.0);
  // No pair at all: 0, not NaN.
  EXPECT_EQ(mean_abs_difference(ref, std::vector<double>{}), 0.0);
}

TEST(MeanAbsDifference, RoundsLiveValuesToSixDigits) {
  // 1.000004 prints as "1": no difference. 1.000006 prints as "1.00001".
  EXPECT_EQ(mean_abs_difference(std::vector<double>{1.0}, std::vector<double>{1.000004}), 0.0);
  EXPECT_EQ(mean_abs_difference(std::vector<double>{1.0}, std::vector<double>{1.000006}),
            1.00001 - 1.0);
}

TEST(MeanAbsDifference, StopsAtNonFiniteLiveValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> ref = {1, 2, 3};
  // Pairs stop before the NaN: K = 1, so e = |1 - 2| / 1.
  EXPECT_DOUBLE_EQ(mean_abs_difference(ref, std::vector<double>{2, nan, 100}), 1.0);
  EXPECT_EQ(mean_abs_difference(ref, std::vector<double>{nan, 5, 5}), 0.0);
  EXPECT_EQ(mean_abs_difference(ref, std::vector<double>{std::numeric_limits<double>::infinity()}),
            0.0);
}

// The worked example of §6 (liver.scn): dofs has 181 points (543 scalars),
// spheres 34 points (102 scalars); one dofs position scalar differs by 0.5 at
// T=1.98; weights 2 (Liver + Visu) and 1.
TEST(StateComparer, LiverWorkedExample) {
  const double dt = 0.02;
  const int steps = 100;
  std::vector<double> dofs(543), spheres(102);
  for (std::size_t i = 0; i < dofs.size(); ++i) dofs[i] = round_g6(std::sin(0.1 * i));
  for (std::size_t i = 0; i < spheres.size(); ++i) spheres[i] = round_g6(std::cos(0.3 * i));
  dofs[100] = 1.25;  // 1.25 and 1.75 are exact: the difference is exactly 0.5

  StateComparer dofs_cmp({make_block(0, dofs), make_block(1.98, dofs)}, dt);
  StateComparer spheres_cmp({make_block(0, spheres), make_block(1.98, spheres)}, dt);
  double t = 0.0;
  for (int k = 0; k < steps; ++k) {
    std::vector<double> live = dofs;
    if (k == steps - 1) live[100] = 1.75;
    dofs_cmp.on_step_begin(t, live.data(), live.size(), nullptr, 0, 181);
    spheres_cmp.on_step_begin(t, spheres.data(), spheres.size(), nullptr, 0, 34);
    t += dt;
  }
  EXPECT_EQ(dofs_cmp.compared_blocks(), 2);
  EXPECT_EQ(spheres_cmp.compared_blocks(), 2);
  EXPECT_DOUBLE_EQ(dofs_cmp.error(), (0.5 / 543) / 181);
  EXPECT_NEAR(dofs_cmp.error(), 5.087e-6, 0.001e-6);
  EXPECT_DOUBLE_EQ(dofs_cmp.total_error(), 0.5 / 543);
  EXPECT_EQ(spheres_cmp.error(), 0.0);

  const double value = scene_value({{dofs_cmp.error(), 2}, {spheres_cmp.error(), 1}});
  EXPECT_NEAR(value, 3.39e-6, 0.005e-6);
  EXPECT_TRUE(scene_passes(value, 1e-4));
  EXPECT_FALSE(scene_passes(value, 1e-6));
}

TEST(StateComparer, SumsXAndVOverBlocks) {
  // Two points of Vec2 (4 scalars). Block 0: X off by 0.4 in one scalar,
  // V off by 2 in two scalars. Block 1 (t = 0.01): X off by 1 in all scalars.
  StateComparer cmp({make_block(0, {0, 0, 0, 0}, {1, 1, 1, 1}), make_block(0.01, {0, 0, 0, 0})},
                    0.01);
  const std::vector<double> x0 = {0, 0.4, 0, 0}, v0 = {3, 1, 3, 1}, x1 = {1, -1, 1, -1};
  cmp.on_step_begin(0.0, x0.data(), 4, v0.data(), 4, 2);
  cmp.on_step_begin(0.01, x1.data(), 4, v0.data(), 4, 2);
  const double e_x0 = 0.4 / 4, e_v0 = 4.0 / 4, e_x1 = 4.0 / 4;
  EXPECT_DOUBLE_EQ(cmp.error(), e_x0 / 2 + e_v0 / 2 + e_x1 / 2);
  EXPECT_DOUBLE_EQ(cmp.total_error(), e_x0 + e_v0 + e_x1);
  ASSERT_EQ(cmp.results().size(), 2u);
  EXPECT_DOUBLE_EQ(cmp.results()[0].contribution, e_x0 / 2 + e_v0 / 2);
}

TEST(StateComparer, MissingLiveVelocitiesAndEmptyStatesCompareNothing) {
  StateComparer cmp({make_block(0, {1, 2}, {5, 5})}, 0.01);
  const std::vector<double> x = {1, 3};
  cmp.on_step_begin(0.0, x.data(), 2, nullptr, 0, 1);  // V= line finds no velocities
  EXPECT_DOUBLE_EQ(cmp.error(), 0.5);

  // P = 0: the e / P contribution is skipped, the plain sum is still kept.
  StateComparer empty({make_block(0, {1, 2})}, 0.01);
  empty.on_step_begin(0.0, x.data(), 2, nullptr, 0, 0);
  EXPECT_EQ(empty.error(), 0.0);
  EXPECT_DOUBLE_EQ(empty.total_error(), 0.5);
  EXPECT_EQ(empty.compared_blocks(), 1);
}

// Reading schedule: blocks at 0 and 0.99, dt 0.01, accumulated clock. The
// live state holds the step index, so a block compared at the wrong step
// gives a non-zero error.
TEST(StateComparer, ComparesEachBlockAtItsStep) {
  const double dt = 0.01;
  auto run = [&](int steps) {
    StateComparer cmp({make_block(0, {0}), make_block(0.99, {99})}, dt);
    double t = 0.0;
    for (int k = 0; k < steps; ++k) {
      const double x = k;
      cmp.on_step_begin(t, &x, 1, nullptr, 0, 1);
      t += dt;
    }
    return cmp;
  };
  const StateComparer full = run(100);
  EXPECT_EQ(full.compared_blocks(), 2);
  EXPECT_EQ(full.error(), 0.0);
  // The clock at step 99 is not exactly 0.99; the 0.001*dt margin absorbs it.
  double t99 = 0.0;
  for (int k = 0; k < 99; ++k) t99 += dt;
  EXPECT_NE(t99, 0.99);
  EXPECT_EQ(full.results()[1].event_time, t99);
  EXPECT_EQ(full.results()[1].block_time, 0.99);

  // One step fewer: the last block is never due, which is not an error.
  const StateComparer short_run = run(99);
  EXPECT_EQ(short_run.compared_blocks(), 1);
  EXPECT_EQ(short_run.error(), 0.0);
}

TEST(StateComparer, MarginCatchesClockBelowPrintedTime) {
  // dt 0.01: the clock at step 10 is 0.09999999999999999 < 0.1. Unlike the
  // topology comparer, the state comparer still compares "T= 0.1" at step 10.
  StateComparer cmp({make_block(0, {0}), make_block(0.1, {10})}, 0.01);
  double t = 0.0;
  for (int k = 0; k < 12; ++k) {
    if (k == 10) {
      ASSERT_LT(t, 0.1);
    }
    const double x = k;
    cmp.on_step_begin(t, &x, 1, nullptr, 0, 1);
    t += 0.01;
  }
  EXPECT_EQ(cmp.compared_blocks(), 2);
  EXPECT_EQ(cmp.error(), 0.0);
}

TEST(StateComparer, ComparesOnlyTheLastOfSeveralDueBlocks) {
  // At t = 0.01 the blocks 0.005 and 0.01 are both due: only 0.01 is compared.
  StateComparer cmp({make_block(0, {0}), make_block(0.005, {7}), make_block(0.01, {1}),
                     make_block(0.5, {50})},
                    0.01);
  double t = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double x = k;
    cmp.on_step_begin(t, &x, 1, nullptr, 0, 1);
    t += 0.01;
  }
  ASSERT_EQ(cmp.compared_blocks(), 2);
  EXPECT_EQ(cmp.results()[0].block_time, 0.0);
  EXPECT_EQ(cmp.results()[1].block_time, 0.01);
  EXPECT_EQ(cmp.error(), 0.0);  // 0.005 (value 7) was skipped
}

TEST(StateComparer, MarginIsAThousandthOfDt) {
  // Block printed at 0.1000005 with dt = 0.01: due at t = 0.1 only if
  // 0.1000005 <= 0.1 + 1e-5, which holds; 0.10002 is beyond the margin.
  StateComparer near({make_block(0.1000005, {0})}, 0.01);
  StateComparer far({make_block(0.10002, {0})}, 0.01);
  const double x = 0;
  near.on_step_begin(0.1, &x, 1, nullptr, 0, 1);
  far.on_step_begin(0.1, &x, 1, nullptr, 0, 1);
  EXPECT_EQ(near.compared_blocks(), 1);
  EXPECT_EQ(far.compared_blocks(), 0);
  far.on_step_begin(0.11, &x, 1, nullptr, 0, 1);
  EXPECT_EQ(far.compared_blocks(), 1);
}

TEST(SceneVerdict, WeightsAndThreshold) {
  EXPECT_DOUBLE_EQ(scene_value({{3.0, 1}, {0.0, 2}}), 1.0);
  EXPECT_DOUBLE_EQ(scene_value({{2e-4, 1}}), 2e-4);
  EXPECT_TRUE(std::isnan(scene_value({})));
  EXPECT_TRUE(scene_passes(scene_value({}), 1e-4));  // no comparer: NaN passes
  EXPECT_TRUE(scene_passes(1e-4, 1e-4));             // equality passes
  EXPECT_FALSE(scene_passes(std::nextafter(1e-4, 1.0), 1e-4));
}

}  // namespace
}  // namespace sinew::regression
