// Text → value parsing with SOFA's rules (spec/framework.md §2.2, trap T13).
#include "core/parse.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace parse = sinew::parse;
using sinew::Vec3;
using sinew::VecN;

// ---------------------------------------------------------------- scalars

// §2.2: trailing garbage after a valid numeric prefix is ignored silently.
TEST(ParseDouble, ValidPrefixIsAcceptedAndGarbageIgnored) {
  double v = 7;
  EXPECT_TRUE(parse::read("1.5abc", v));
  EXPECT_EQ(v, 1.5);
}

// §2.2: a non-numeric token gives value 0 and a failure.
TEST(ParseDouble, NonNumericTokenGivesZeroAndFailure) {
  double v = 7;
  EXPECT_FALSE(parse::read("abc", v));
  EXPECT_EQ(v, 0.0);
}

TEST(ParseDouble, ExponentAndSignAreRead) {
  double v = 0;
  EXPECT_TRUE(parse::read("  -2.5e-3 ", v));
  EXPECT_EQ(v, -2.5e-3);
  EXPECT_TRUE(parse::read("+4", v));
  EXPECT_EQ(v, 4.0);
  EXPECT_TRUE(parse::read(".5", v));
  EXPECT_EQ(v, 0.5);
}

TEST(ParseDouble, OnlyTheFirstTokenIsRead) {
  double v = 0;
  EXPECT_TRUE(parse::read("2 3 4", v));
  EXPECT_EQ(v, 2.0);
}

TEST(ParseInt, NonNumericTokenGivesZeroAndFailure) {
  int v = 9;
  EXPECT_FALSE(parse::read("x12", v));
  EXPECT_EQ(v, 0);
  EXPECT_TRUE(parse::read("-3", v));
  EXPECT_EQ(v, -3);
  // An int stops at the decimal point.
  EXPECT_TRUE(parse::read("12.7", v));
  EXPECT_EQ(v, 12);
}

TEST(ParseUnsigned, NegativeValueBecomesZeroAndFailure) {
  unsigned v = 5;
  EXPECT_FALSE(parse::read("-4", v));
  EXPECT_EQ(v, 0u);
}

TEST(ParseFloat, ValueIsRoundedToSinglePrecision) {
  float v = 0;
  EXPECT_TRUE(parse::read("0.1", v));
  EXPECT_EQ(v, 0.1f);
}

// ---------------------------------------------------------------- bools

// §2.2: first char T/t → true, F/f → false.
TEST(ParseBool, LettersTAndFDecideByFirstCharacter) {
  bool v = false;
  EXPECT_TRUE(parse::read("T", v));
  EXPECT_TRUE(v);
  EXPECT_TRUE(parse::read("false", v));
  EXPECT_FALSE(v);
  EXPECT_TRUE(parse::read("true", v));
  EXPECT_TRUE(v);
  EXPECT_TRUE(parse::read("f", v));
  EXPECT_FALSE(v);
  EXPECT_TRUE(parse::read("tomato", v));  // only the first character counts
  EXPECT_TRUE(v);
}

// §2.2: first char digit or '-' → integer prefix, true iff ≠ 0.
TEST(ParseBool, DigitsAndMinusAreIntegersNonZeroMeansTrue) {
  bool v = true;
  EXPECT_TRUE(parse::read("0", v));
  EXPECT_FALSE(v);
  EXPECT_TRUE(parse::read("2", v));
  EXPECT_TRUE(v);
  v = false;
  EXPECT_TRUE(parse::read("-1", v));
  EXPECT_TRUE(v);
  EXPECT_TRUE(parse::read("1", v));
  EXPECT_TRUE(v);
}

// §2.2: anything else ("yes") is a failure and leaves the value unchanged.
TEST(ParseBool, YesIsAFailureAndLeavesTheValueUnchanged) {
  bool v = false;
  EXPECT_FALSE(parse::read("yes", v));
  EXPECT_FALSE(v);
  v = true;
  EXPECT_FALSE(parse::read("no", v));
  EXPECT_TRUE(v);
}

TEST(ParseString, WholeTextVerbatim) {
  std::string s;
  EXPECT_TRUE(parse::read("  a b  ", s));
  EXPECT_EQ(s, "  a b  ");
}

// ---------------------------------------------------------------- vectors

TEST(ParseVector, FlatListOfDoubles) {
  std::vector<double> v{9, 9, 9, 9, 9};
  EXPECT_TRUE(parse::read("1 2.5\n-3", v));
  EXPECT_EQ(v, (std::vector<double>{1, 2.5, -3}));
}

// §2.2: empty text clears a container, success.
TEST(ParseVector, EmptyTextClearsTheContainer) {
  std::vector<double> v{1, 2};
  EXPECT_TRUE(parse::read("", v));
  EXPECT_TRUE(v.empty());
}

// §2.2 / T13: a trailing incomplete element is silently dropped (success).
TEST(ParseVector, TrailingIncompleteElementIsDroppedSilently) {
  std::vector<Vec3> v;
  EXPECT_TRUE(parse::read("0 0 0 1 2 3 4 5", v));
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1], Vec3(1, 2, 3));
}

// §2.2: a bad token in the middle is a failure; complete elements read before it are kept.
TEST(ParseVector, BadMiddleTokenKeepsEarlierElements) {
  std::vector<Vec3> v;
  EXPECT_FALSE(parse::read("1 2 3 4 x 6 7 8 9", v));
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0], Vec3(1, 2, 3));

  std::vector<double> d;
  EXPECT_FALSE(parse::read("1 2 oops 4", d));
  EXPECT_EQ(d, (std::vector<double>{1, 2}));
}

TEST(ParseVector, FlatGroupsOfDynamicWidth) {
  std::vector<double> v;
  EXPECT_TRUE(parse::read_flat("1 2 3 4 5 6 7 8 9 10 11 12 13 14 15", 7, v));
  EXPECT_EQ(v.size(), 14u);  // the 15th scalar starts an incomplete element
  EXPECT_EQ(v[13], 14.0);
}

TEST(ParseVector, IndexTuplesAreReadInGroups) {
  std::vector<std::array<unsigned, 3>> tris;
  EXPECT_TRUE(parse::read("0 1 2 2 3 0 4", tris));
  ASSERT_EQ(tris.size(), 2u);
  EXPECT_EQ(tris[1], (std::array<unsigned, 3>{2, 3, 0}));
}

// ---------------------------------------------------------------- index lists

// §2.2: "A-B" expands to A..B inclusive.
TEST(ParseIndexList, AscendingRange) {
  std::vector<unsigned> v;
  EXPECT_TRUE(parse::read("2-5", v));
  EXPECT_EQ(v, (std::vector<unsigned>{2, 3, 4, 5}));
}

// §2.2: descending when A > B.
TEST(ParseIndexList, DescendingRange) {
  std::vector<unsigned> v;
  EXPECT_TRUE(parse::read("5-2", v));
  EXPECT_EQ(v, (std::vector<unsigned>{5, 4, 3, 2}));
}

// §2.2: "A-B-s" uses step s.
TEST(ParseIndexList, RangeWithStep) {
  std::vector<unsigned> v;
  EXPECT_TRUE(parse::read("0-10-5", v));
  EXPECT_EQ(v, (std::vector<unsigned>{0, 5, 10}));
}

TEST(ParseIndexList, RangesMixWithPlainIndices) {
  std::vector<unsigned> v;
  EXPECT_TRUE(parse::read("7 0-2 9", v));
  EXPECT_EQ(v, (std::vector<unsigned>{7, 0, 1, 2, 9}));
}

// §2.2: negative numbers in unsigned lists become 0 (failure).
TEST(ParseIndexList, NegativeIndexBecomesZeroAndFailure) {
  std::vector<unsigned> v;
  EXPECT_FALSE(parse::read("1 -2 3", v));
  EXPECT_EQ(v, (std::vector<unsigned>{1, 0, 3}));
}

// §2.2: a bad token becomes 0 (and the rest is still read).
TEST(ParseIndexList, BadTokenBecomesZero) {
  std::vector<int> v;
  EXPECT_FALSE(parse::read("4 abc 6", v));
  EXPECT_EQ(v, (std::vector<int>{4, 0, 6}));
}

TEST(ParseIndexList, SignedListKeepsNegativeValues) {
  std::vector<int> v;
  EXPECT_TRUE(parse::read("-3 4", v));
  EXPECT_EQ(v, (std::vector<int>{-3, 4}));
}

// ---------------------------------------------------------------- fixed vectors

// §2.2: too few numbers → failure, missing components unchanged.
TEST(ParseVec3, TooFewNumbersLeaveMissingComponentsUnchanged) {
  Vec3 v(7, 8, 9);
  EXPECT_FALSE(parse::read("1 2", v));
  EXPECT_EQ(v, Vec3(1, 2, 9));
}

TEST(ParseVec3, ThreeNumbersSucceedAndExtraTokensAreIgnored) {
  Vec3 v(7, 8, 9);
  EXPECT_TRUE(parse::read("1 2 3 4", v));
  EXPECT_EQ(v, Vec3(1, 2, 3));
}

TEST(ParseVec3, BadComponentBecomesZeroAndStops) {
  Vec3 v(7, 8, 9);
  EXPECT_FALSE(parse::read("1 q 3", v));
  EXPECT_EQ(v, Vec3(1, 0, 9));
}

// ---------------------------------------------------------------- strings

TEST(ParseStringList, WhitespaceTokens) {
  std::vector<std::string> v;
  EXPECT_TRUE(parse::read("a  b\tc", v));
  EXPECT_EQ(v, (std::vector<std::string>{"a", "b", "c"}));
}

// §2.2: bracketed quoted form ["a", "b"] (spaces inside quotes are kept).
TEST(ParseStringList, BracketedQuotedForm) {
  std::vector<std::string> v;
  EXPECT_TRUE(parse::read(R"( ["first", "second one"])", v));
  EXPECT_EQ(v, (std::vector<std::string>{"first", "second one"}));
}

// ---------------------------------------------------------------- writing

// §2.2: values are written back with 6 significant digits.
TEST(FormatDouble, SixSignificantDigits) {
  EXPECT_EQ(parse::format_double(3.14159265358979), "3.14159");
  EXPECT_EQ(parse::format_double(1234567.0), "1.23457e+06");
  EXPECT_EQ(parse::format_double(0.1), "0.1");
  EXPECT_EQ(parse::format_double(100.0), "100");
  EXPECT_EQ(parse::format_double(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(parse::format_double(0.0), "0");
}

TEST(FormatDouble, ListsAreSeparatedBySingleSpaces) {
  EXPECT_EQ(parse::to_text(std::vector<double>{1, 0.5, -2}), "1 0.5 -2");
  EXPECT_EQ(parse::to_text(std::vector<unsigned>{3, 1}), "3 1");
  EXPECT_EQ(parse::to_text(Vec3(1.0 / 3.0, 2, 0)), "0.333333 2 0");
  EXPECT_EQ(parse::to_text(std::vector<Vec3>{Vec3(1, 2, 3), Vec3(4, 5, 6)}), "1 2 3 4 5 6");
  EXPECT_EQ(parse::to_text(true), "1");
}

// ---------------------------------------------------------------- Rigid3d mass (RigidMass<3> >>)

TEST(ParseRigid3Mass, MatrixDecorationsAreOptional) {
  std::vector<double> v;
  const std::vector<double> want = {2, 0.5, 1, 0, 0, 0, 3, 0, 0, 0, 5};
  EXPECT_TRUE(parse::read_rigid3_mass("2 0.5 [1 0 0,0 3 0,0 0 5]", v));
  EXPECT_EQ(v, want);
  EXPECT_TRUE(parse::read_rigid3_mass("2 0.5 [1 0 0 0 3 0 0 0 5]", v));
  EXPECT_EQ(v, want);
  EXPECT_TRUE(parse::read_rigid3_mass("2 0.5 1 0 0 0 3 0 0 0 5", v));
  EXPECT_EQ(v, want);
  EXPECT_TRUE(parse::read_rigid3_mass("  2 0.5\n[ 1 0 0 , 0 3 0 , 0 0 5 ]  trailing", v));
  EXPECT_EQ(v, want);
}

TEST(ParseRigid3Mass, ShortTextGivesFewerValuesAndGarbageFails) {
  std::vector<double> v;
  EXPECT_TRUE(parse::read_rigid3_mass("0.01", v));
  EXPECT_EQ(v, (std::vector<double>{0.01}));
  EXPECT_FALSE(parse::read_rigid3_mass("1 1 [1 0 x]", v));
  EXPECT_EQ(v, (std::vector<double>{1, 1, 1, 0}));
  // A second '[' is not a matrix decoration (SOFA skips one only).
  EXPECT_FALSE(parse::read_rigid3_mass("1 1 [[1 0 0 0 1 0 0 0 1]]", v));
}

// Found by fuzz_field_values: "3E33331" read as +inf and was written back as "inf",
// which reads as 0. std::istream (SOFA's reader) stores ±max and fails on overflow.
TEST(ParseDouble, OverflowIsTheLargestFiniteValueAndAFailure) {
  double d = 0;
  EXPECT_FALSE(parse::read("3E33331", d));
  EXPECT_EQ(d, std::numeric_limits<double>::max());
  EXPECT_FALSE(parse::read("-1e400", d));
  EXPECT_EQ(d, -std::numeric_limits<double>::max());
  float f = 0;
  EXPECT_FALSE(parse::read("1e39", f));
  EXPECT_EQ(f, std::numeric_limits<float>::max());
  EXPECT_FALSE(parse::read("1e400", f));
  EXPECT_EQ(f, std::numeric_limits<float>::max());
  // Underflow is not a failure: zero (or a denormal), as strtod.
  EXPECT_TRUE(parse::read("1e-400", d));
  EXPECT_EQ(d, 0.0);
  // A list stops at the overflowing number (as a stream read would).
  std::vector<double> v;
  EXPECT_FALSE(parse::read("1 1e400 2", v));
  EXPECT_EQ(v, std::vector<double>{1.0});
  Vec3 p = Vec3::Zero();
  EXPECT_FALSE(parse::read("1 1e999 3", p));
  EXPECT_TRUE(p.allFinite());
}

// Found by fuzz_field_values: "888888888-8" expanded to 888 million indices (3.5 GB).
// A range is a size from the scene: refused (a failure the loader warns about) when it
// would not fit in memory; ranges at the ends of long long do not overflow.
TEST(ParseIndexList, RangeBeyondMemoryIsRefusedNotAllocated) {
  std::vector<unsigned> v;
  EXPECT_FALSE(parse::read("1 0-9000000000000000000 2", v));
  EXPECT_EQ(v, (std::vector<unsigned>{1, 2}));
  std::vector<int> w;
  EXPECT_TRUE(parse::read("9223372036854775805-9223372036854775807", w));
  EXPECT_EQ(w.size(), 3u);
  EXPECT_TRUE(parse::read("10-4-3", v));
  EXPECT_EQ(v, (std::vector<unsigned>{10, 7, 4}));
}
