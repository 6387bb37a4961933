// Lists of reals read numbers written without a space between them as
// std::istream does (SOFA scenes have "0 0-0.707107 0.707107"), while scalars
// and index ranges keep their own rules.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/field.h"
#include "core/parse.h"
#include "core/value_text.h"

namespace parse = sinew::parse;

TEST(ParseJoinedNumbers, ListSplitsANumberFollowedByASignedOne) {
  std::vector<double> v;
  EXPECT_TRUE(parse::read_flat("0 0-0.707107 0.707107", 1, v));
  EXPECT_EQ(v, (std::vector<double>{0, 0, -0.707107, 0.707107}));
  EXPECT_TRUE(parse::read_flat("1e-3+2 .5.25", 1, v));  // exponent sign stays in its number; ".5.25" is 0.5, 0.25
  EXPECT_EQ(v, (std::vector<double>{1e-3, 2, 0.5, 0.25}));
}

TEST(ParseJoinedNumbers, GroupsCountTheSplitNumbers) {
  std::vector<double> v;
  EXPECT_TRUE(parse::read_flat("1 2 3 0 0-0.6 0.8  4 5", 7, v));
  ASSERT_EQ(v.size(), 7u);  // the incomplete second element is dropped
  EXPECT_EQ(v[5], -0.6);
  EXPECT_EQ(parse::count_list_numbers("1 2 3 0 0-0.6 0.8"), 7u);
  EXPECT_EQ(parse::count_list_numbers("1 abc 2x"), 3u);
}

TEST(ParseJoinedNumbers, GarbageAfterANumberIsStillOnlyItsPrefix) {
  std::vector<double> v;
  EXPECT_TRUE(parse::read_flat("1.5abc 2", 1, v));
  EXPECT_EQ(v, (std::vector<double>{1.5, 2}));
  EXPECT_EQ(parse::first_partial_number("0-0.5 1", true), "");
  EXPECT_EQ(parse::first_partial_number("0-0.5 1", false), "0-0.5");
  EXPECT_EQ(parse::first_partial_number("0-0.5x", true), "0-0.5x");
}

TEST(ParseJoinedNumbers, ScalarsAndIndexRangesAreUnchanged) {
  double d = 0;
  EXPECT_TRUE(parse::read("0-0.5", d));
  EXPECT_EQ(d, 0.0);
  std::vector<unsigned> idx;
  EXPECT_TRUE(parse::read("1-3", idx));
  EXPECT_EQ(idx, (std::vector<unsigned>{1, 2, 3}));
}
