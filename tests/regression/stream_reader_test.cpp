// StreamReader must read exactly what `std::istream >>` reads, since that is
// how SOFA's comparer decides where a reference vector ends.
#include "regression/stream_reader.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <climits>
#include <cmath>
#include <random>
#include <sstream>

namespace sinew::regression {
namespace {

// All doubles read from `text` by StreamReader, up to the first failure.
std::vector<double> read_all(std::string_view text) {
  std::vector<double> out;
  StreamReader reader(text);
  for (double v; reader.read(v);) out.push_back(v);
  return out;
}

std::vector<double> read_all_with_istream(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  for (double v; in >> v;) out.push_back(v);
  return out;
}

TEST(StreamReader, ReadsPlainDecimals) {
  EXPECT_EQ(read_all(" -9 0.5\t1e-09 +3 -.25 1. 2.77556e-17\r"),
            (std::vector<double>{-9, 0.5, 1e-9, 3, -0.25, 1.0, 2.77556e-17}));
}

TEST(StreamReader, StopsAtNanAndInf) {
  EXPECT_EQ(read_all("1 2 nan 4"), (std::vector<double>{1, 2}));
  EXPECT_EQ(read_all("1 -nan 4"), (std::vector<double>{1}));
  EXPECT_EQ(read_all("inf 4"), (std::vector<double>{}));
  EXPECT_EQ(read_all("5 -inf"), (std::vector<double>{5}));
}

TEST(StreamReader, SplitsLikeNumGet) {
  // "1.5abc": 1.5 is read, then "abc" fails.
  EXPECT_EQ(read_all("1.5abc 2"), (std::vector<double>{1.5}));
  // A second '.' or a '.' after the exponent starts a new number.
  EXPECT_EQ(read_all("1.2.3"), (std::vector<double>{1.2, 0.3}));
  EXPECT_EQ(read_all("1e5.3"), (std::vector<double>{1e5, 0.3}));
  // A hex prefix is not part of a decimal number: "0" then "x1p3" fails.
  EXPECT_EQ(read_all("0x1p3"), (std::vector<double>{0.0}));
  // An incomplete exponent makes the whole number fail.
  EXPECT_EQ(read_all("7 1e"), (std::vector<double>{7}));
  EXPECT_EQ(read_all("7 1e+ 8"), (std::vector<double>{7}));
}

TEST(StreamReader, OverflowFailsUnderflowIsAccepted) {
  StreamReader over("1e400");
  double v = 0;
  EXPECT_FALSE(over.read(v));
  EXPECT_EQ(v, DBL_MAX);
  StreamReader under("1e-400 4.9e-324");
  EXPECT_TRUE(under.read(v));
  EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(under.read(v));
  EXPECT_EQ(v, std::numeric_limits<double>::denorm_min());
}

TEST(StreamReader, FailureIsStickyAndSetsZero) {
  StreamReader reader("abc 5");
  double v = 3;
  EXPECT_FALSE(reader.read(v));
  EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(reader.failed());
  std::string_view word;
  EXPECT_FALSE(reader.read_word(word));
}

TEST(StreamReader, ReadsIntegersAndWords) {
  StreamReader reader("  Edges= 96 -4 +7 9223372036854775807 x");
  std::string_view word;
  ASSERT_TRUE(reader.read_word(word));
  EXPECT_EQ(word, "Edges=");
  long long a = 0, b = 0, c = 0, d = 0;
  EXPECT_TRUE(reader.read(a));
  EXPECT_TRUE(reader.read(b));
  EXPECT_TRUE(reader.read(c));
  EXPECT_TRUE(reader.read(d));
  EXPECT_EQ(a, 96);
  EXPECT_EQ(b, -4);
  EXPECT_EQ(c, 7);
  EXPECT_EQ(d, LLONG_MAX);
  EXPECT_FALSE(reader.read(a));
  StreamReader overflow("9223372036854775808 -9223372036854775808");
  EXPECT_FALSE(overflow.read(a));
  EXPECT_EQ(a, LLONG_MAX);
  StreamReader min("-9223372036854775808");
  EXPECT_TRUE(min.read(a));
  EXPECT_EQ(a, LLONG_MIN);
}

TEST(StreamReader, AgreesWithIstreamOnRandomText) {
  // Random strings over the characters that matter to number parsing.
  const std::string alphabet = "0123456789..eE+-  \tnaix";
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<int> length(0, 24);
  for (int i = 0; i < 100000; ++i) {
    std::string text;
    for (int n = length(rng); n > 0; --n) text += alphabet[pick(rng)];
    const auto ours = read_all(text);
    const auto theirs = read_all_with_istream(text);
    ASSERT_EQ(ours.size(), theirs.size()) << "'" << text << "'";
    for (std::size_t k = 0; k < ours.size(); ++k) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(ours[k]), std::bit_cast<std::uint64_t>(theirs[k]))
          << "'" << text << "'";
    }
  }
}

TEST(SplitLines, BehavesLikeGetline) {
  EXPECT_EQ(split_lines("a\nb\n"), (std::vector<std::string_view>{"a", "b"}));
  EXPECT_EQ(split_lines("a\r\n\nb"), (std::vector<std::string_view>{"a\r", "", "b"}));
  EXPECT_TRUE(split_lines("").empty());
}

}  // namespace
}  // namespace sinew::regression
