// State reference file format (regression-protocol.md §3.4).
#include "regression/state_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sinew::regression {
namespace {

TEST(StateFile, ParsesBlocksAndVectorLines) {
  const auto blocks = parse_state_text(
      "T= 0\n"
      "  X= -9 0 0.5\n"
      "  V= 0 0 0\n"
      "T= 1.98\n"
      "  X0= 1 2 3\n"  // rest positions: not compared
      "  F= 4 5 6\n"   // forces: not compared
      "  X= -9.31076 -0.291267 2.77556e-17\n");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].time, 0.0);
  ASSERT_EQ(blocks[0].lines.size(), 2u);
  EXPECT_EQ(blocks[0].lines[0].tag, 'X');
  EXPECT_EQ(blocks[0].lines[0].values, (std::vector<double>{-9, 0, 0.5}));
  EXPECT_EQ(blocks[0].lines[1].tag, 'V');
  EXPECT_EQ(blocks[0].lines[1].values, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(blocks[1].time, 1.98);
  ASSERT_EQ(blocks[1].lines.size(), 1u);
  EXPECT_EQ(blocks[1].lines[0].values, (std::vector<double>{-9.31076, -0.291267, 2.77556e-17}));
}

TEST(StateFile, StopsVectorAtFirstNonNumber) {
  const auto blocks = parse_state_text("T= 0\n  X= 1 2 nan 4\n  V= inf 1\n  X= 3 -4e 5\n");
  ASSERT_EQ(blocks.size(), 1u);
  ASSERT_EQ(blocks[0].lines.size(), 3u);
  EXPECT_EQ(blocks[0].lines[0].values, (std::vector<double>{1, 2}));
  EXPECT_TRUE(blocks[0].lines[1].values.empty());
  EXPECT_EQ(blocks[0].lines[2].values, (std::vector<double>{3}));
}

TEST(StateFile, IgnoresUnknownAndEarlyLines) {
  const auto blocks = parse_state_text(
      "  X= 1 2 3\n"  // before any T=: ignored
      "T=0\n"         // no space: not a block header
      "\n"
      "T= 0.5 extra\n"
      "  X=1 2\n"     // no space after the tag: not a vector line
      "\tV= 7\r\n"    // any leading whitespace, '\r' is whitespace
      "T= bogus\n");  // unreadable time reads as 0, as with C++ >>
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].time, 0.5);
  ASSERT_EQ(blocks[0].lines.size(), 1u);
  EXPECT_EQ(blocks[0].lines[0].tag, 'V');
  EXPECT_EQ(blocks[0].lines[0].values, (std::vector<double>{7}));
  EXPECT_EQ(blocks[1].time, 0.0);
}

TEST(StateFile, FormatsBlocksExactly) {
  const double x[] = {-9.0, 0.0, 1.0000001, 2.775557561562891e-17, -0.97925949, 1e-9};
  const double v[] = {0.0, -0.5, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(format_state_block(1.98, x, 6, v, 3),
            "T= 1.98\n  X= -9 0 1 2.77556e-17 -0.979259 1e-09\n  V= 0 -0.5 nan\n");
  EXPECT_EQ(format_state_block(0.09999999999999999, x, 2, nullptr, 0), "T= 0.1\n  X= -9 0\n");
  EXPECT_EQ(format_state_block(0, nullptr, 0, v, 1), "T= 0\n  V= 0\n");
  EXPECT_EQ(format_state_block(0, x, 0, nullptr, 0), "T= 0\n  X= \n");
}

TEST(StateFile, RoundTripsThroughText) {
  std::vector<double> x, v;
  for (int i = 0; i < 30; ++i) {
    x.push_back(std::sin(i) * 19.0);
    v.push_back(std::cos(i) * 1e-3);
  }
  std::string text;
  append_state_block(text, 0.0, x.data(), x.size(), v.data(), v.size());
  append_state_block(text, 0.99, x.data(), x.size(), nullptr, 0);
  const auto blocks = parse_state_text(text);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].time, 0.99);
  ASSERT_EQ(blocks[0].lines.size(), 2u);
  ASSERT_EQ(blocks[1].lines.size(), 1u);
  ASSERT_EQ(blocks[0].lines[0].values.size(), 30u);
  for (int i = 0; i < 30; ++i) {
    EXPECT_NEAR(blocks[0].lines[0].values[i], x[i], 5e-6 * std::fabs(x[i]));
    EXPECT_NEAR(blocks[0].lines[1].values[i], v[i], 5e-6 * std::fabs(v[i]));
  }
  // Writing what was read gives the same text again.
  std::string again;
  const auto& b0 = blocks[0];
  append_state_block(again, b0.time, b0.lines[0].values.data(), 30, b0.lines[1].values.data(), 30);
  append_state_block(again, blocks[1].time, blocks[1].lines[0].values.data(), 30, nullptr, 0);
  EXPECT_EQ(again, text);
}

}  // namespace
}  // namespace sinew::regression
