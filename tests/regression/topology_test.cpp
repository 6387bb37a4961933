// Topology reference format, metric and reading schedule
// (regression-protocol.md §3.5, §5, §7).
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "regression/block_schedule.h"
#include "regression/number_format.h"
#include "regression/topology_compare.h"
#include "regression/topology_file.h"

namespace sinew::regression {
namespace {

// A live topology owning its index arrays.
struct LiveTopology {
  std::array<std::vector<std::uint32_t>, kElementTypeCount> indices;
  TopologyView view() const {
    TopologyView v;
    for (std::size_t t = 0; t < kElementTypeCount; ++t) v.indices[t] = indices[t];
    return v;
  }
};

LiveTopology two_triangles() {
  LiveTopology live;
  live.indices[0] = {0, 1, 1, 2, 2, 0, 2, 3};  // 4 edges
  live.indices[1] = {0, 1, 2, 0, 2, 3};        // 2 triangles
  return live;
}

constexpr const char* kTwoTrianglesText =
    "T= 0.01\n"
    "  Edges= 4\n"
    "0 1 1 2 2 0 2 3\n"
    "  Triangles= 2\n"
    "0 1 2 0 2 3\n"
    "  Quads= 0\n"
    "\n"
    "  Tetrahedra= 0\n"
    "\n"
    "  Hexahedra= 0\n"
    "\n";

TEST(TopologyFile, FormatsBlocksExactly) {
  EXPECT_EQ(format_topology_block(0.01, two_triangles().view()), kTwoTrianglesText);
  LiveTopology hexa;
  hexa.indices[4] = {0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(format_topology_block(0.09999999999999999, hexa.view()),
            "T= 0.1\n  Edges= 0\n\n  Triangles= 0\n\n  Quads= 0\n\n  Tetrahedra= 0\n\n"
            "  Hexahedra= 1\n0 1 2 3 4 5 6 7\n");
}

TEST(TopologyFile, ParsesWhatIsWritten) {
  std::string text = kTwoTrianglesText;
  text += "T= 0.02\n  Tetrahedra= 1\n4 5 6 7\n  Edges= 3\n";  // last header without index line
  const auto blocks = parse_topology_text(text);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].time, 0.01);
  EXPECT_EQ(blocks[0].counts, (std::array<long long, 5>{4, 2, 0, 0, 0}));
  EXPECT_EQ(blocks[0].indices[0], (std::vector<long long>{0, 1, 1, 2, 2, 0, 2, 3}));
  EXPECT_EQ(blocks[0].indices[1], (std::vector<long long>{0, 1, 2, 0, 2, 3}));
  EXPECT_TRUE(blocks[0].indices[2].empty());
  EXPECT_EQ(blocks[1].counts, (std::array<long long, 5>{3, 0, 0, 1, 0}));
  EXPECT_EQ(blocks[1].indices[3], (std::vector<long long>{4, 5, 6, 7}));
  EXPECT_TRUE(blocks[1].indices[0].empty());
}

TEST(TopologyFile, HeaderFollowedByNextBlockHasNoIndices) {
  const auto blocks = parse_topology_text("T= 0\n  Edges= 1\nT= 1\n  Edges= 1\n3 4\n");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_TRUE(blocks[0].indices[0].empty());
  EXPECT_EQ(blocks[1].time, 1.0);
  EXPECT_EQ(blocks[1].indices[0], (std::vector<long long>{3, 4}));
}

TEST(TopologyMetric, CountsDifferences) {
  const TopologyBlock ref = parse_topology_text(kTwoTrianglesText).at(0);
  const LiveTopology same = two_triangles();
  EXPECT_EQ(compare_topology_block(ref, same.view()), (std::array<long long, 5>{}));

  // Count mismatch: |n - m|, elements not inspected.
  LiveTopology fewer = two_triangles();
  fewer.indices[0].resize(2);  // 1 edge instead of 4
  EXPECT_EQ(compare_topology_block(ref, fewer.view()), (std::array<long long, 5>{3, 0, 0, 0, 0}));

  // Same count: 1 per differing element; a rotated triangle differs.
  LiveTopology rotated = two_triangles();
  rotated.indices[1] = {1, 2, 0, 0, 2, 3};
  rotated.indices[0][7] = 9;  // last edge differs in one vertex
  rotated.indices[0][6] = 9;  // ... and in both: still one element
  EXPECT_EQ(compare_topology_block(ref, rotated.view()), (std::array<long long, 5>{1, 1, 0, 0, 0}));

  // Types with reference count 0 are not checked, whatever the live has.
  LiveTopology extra = two_triangles();
  extra.indices[2] = {0, 1, 2, 3};
  extra.indices[4] = {0, 1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(compare_topology_block(ref, extra.view()), (std::array<long long, 5>{}));

  // Live topology larger than the reference: |n - m| as well.
  LiveTopology more = two_triangles();
  more.indices[1].insert(more.indices[1].end(), {4, 5, 6, 7, 8, 9, 1, 2, 3});
  EXPECT_EQ(compare_topology_block(ref, more.view())[1], 3);
}

TEST(TopologyMetric, ShortIndexLineCountsAsDifferent) {
  const TopologyBlock ref = parse_topology_text("T= 0\n  Edges= 3\n0 1 1 2 2\n").at(0);
  LiveTopology live;
  live.indices[0] = {0, 1, 1, 2, 2, 0};
  EXPECT_EQ(compare_topology_block(ref, live.view())[0], 1);
}

// Writes `count` blocks at the accumulated clock with dt, printed with %g.
std::vector<TopologyBlock> written_blocks(double dt, int count, const LiveTopology& live) {
  std::string text;
  double t = 0.0;
  for (int k = 0; k < count; ++k) {
    append_topology_block(text, t, live.view());
    t += dt;
  }
  return parse_topology_text(text);
}

// Runs `steps` events with the accumulated clock; the live topology is wrong
// at every step, so each compared block adds exactly 1 (one differing edge).
TopologyComparer run(double dt, int steps, std::vector<TopologyBlock> blocks) {
  LiveTopology wrong = two_triangles();
  wrong.indices[0][0] = 7;
  TopologyComparer cmp(std::move(blocks));
  double t = 0.0;
  for (int k = 0; k < steps; ++k) {
    cmp.on_step_begin(t, wrong.view());
    t += dt;
  }
  return cmp;
}

TEST(TopologyComparer, SkipsBlocksPrintedAboveTheClock) {
  // dt 0.01: the clock reads 0.09999999999999999 ... 0.13999999999999999 at
  // steps 10..14, so the blocks printed 0.1 ... 0.14 are consumed, never compared.
  const TopologyComparer cmp = run(0.01, 30, written_blocks(0.01, 30, two_triangles()));
  EXPECT_EQ(cmp.compared_blocks(), 25);
  EXPECT_EQ(cmp.total_error(), 25);
  EXPECT_EQ(cmp.errors_by_type()[0], 25);
  std::vector<double> skipped;
  for (int k = 0; k < 30; ++k) {
    const double printed = round_g6(k * 0.01);
    bool compared = false;
    for (double t : cmp.compared_times()) compared = compared || t == printed;
    if (!compared) skipped.push_back(printed);
  }
  EXPECT_EQ(skipped, (std::vector<double>{0.1, 0.11, 0.12, 0.13, 0.14}));
}

TEST(TopologyComparer, OtherTimeStepsSkipOtherBlocks) {
  // dt 0.05 (Tetra2TriangleTopologicalMapping): blocks 0.4 ... 0.55 skipped.
  const TopologyComparer cmp = run(0.05, 30, written_blocks(0.05, 30, two_triangles()));
  EXPECT_EQ(cmp.compared_blocks(), 26);
  for (double t : cmp.compared_times()) {
    EXPECT_TRUE(t < 0.4 || t > 0.55) << t;
  }
}

TEST(TopologyComparer, TruncatedFileComparesUntilItsEnd) {
  // 21 blocks (like the truncated stored files), 30 steps: the 16 blocks
  // outside 0.1 ... 0.14 are compared, the end of file is not an error.
  const TopologyComparer cmp = run(0.01, 30, written_blocks(0.01, 21, two_triangles()));
  EXPECT_EQ(cmp.compared_blocks(), 16);
  EXPECT_EQ(cmp.total_error(), 16);
}

TEST(TopologyComparer, MatchingTopologyGivesZero) {
  TopologyComparer cmp(written_blocks(0.01, 30, two_triangles()));
  const LiveTopology live = two_triangles();
  double t = 0.0;
  for (int k = 0; k < 30; ++k, t += 0.01) cmp.on_step_begin(t, live.view());
  EXPECT_EQ(cmp.total_error(), 0);
  EXPECT_EQ(cmp.compared_blocks(), 25);
}

// Loop mode (ReadTopology's `loop`): at the end the file starts again, its times shifted by the
// last time read, within the same event: at t = 0.5 the first block of the second pass (0 + 0.5)
// replaces the last block of the first, as SOFA's reader does.
TEST(BlockSchedule, LoopRestartsShiftedByTheLastTime) {
  BlockSchedule s({0.0, 0.25, 0.5});
  s.set_loop(true);
  std::vector<std::optional<std::size_t>> due;
  for (int k = 0; k < 6; ++k) {
    const double t = 0.25 * k;
    due.push_back(s.advance(t + 1e-8, t));
  }
  const std::vector<std::optional<std::size_t>> want{0, 1, 0, 1, 0, 1};
  EXPECT_EQ(due, want);
  EXPECT_DOUBLE_EQ(s.offset(), 1.0);
  EXPECT_FALSE(s.at_end());
}

// A looping file whose last time is 0 never moves the clock on: read once, no hang.
TEST(BlockSchedule, LoopOverAFileAtTimeZeroStops) {
  BlockSchedule s({0.0, 0.0});
  s.set_loop(true);
  EXPECT_EQ(s.advance(1e-8, 0.0), std::optional<std::size_t>(1));
  EXPECT_EQ(s.advance(1.0 + 1e-8, 1.0), std::nullopt);
}

// Tiny positive times would need 1e300 passes: each event is bounded, nothing hangs.
TEST(BlockSchedule, LoopOverTinyTimesIsBounded) {
  BlockSchedule s({1e-300});
  s.set_loop(true);
  EXPECT_EQ(s.advance(1.0 + 1e-8, 1.0), std::optional<std::size_t>(0));
}

}  // namespace
}  // namespace sinew::regression
