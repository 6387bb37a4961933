// format_g6 / round_g6: the text every scalar of a reference goes through.
#include "regression/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

namespace sinew::regression {
namespace {

std::string printf_g6(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

TEST(FormatG6, MatchesTable) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    double value;
    const char* text;
  } table[] = {
      {0.0, "0"},
      {-0.0, "-0"},
      {1.98, "1.98"},
      {-0.979259, "-0.979259"},
      {2.77556e-17, "2.77556e-17"},
      {1e-9, "1e-09"},
      {nan, "nan"},
      {-nan, "-nan"},
      {inf, "inf"},
      {-inf, "-inf"},
      {100.0, "100"},
      {123456.0, "123456"},
      {1234567.0, "1.23457e+06"},
      {999999.4, "999999"},
      {999999.5, "1e+06"},  // rounds up into the exponent form
      {0.0001, "0.0001"},   // smallest exponent still printed in fixed form
      {0.00001, "1e-05"},
      {0.000123456789, "0.000123457"},
      {1e100, "1e+100"},
      {9.999994, "9.99999"},
      {9.999995000001, "10"},  // just above the rounding boundary
      {1.0000049, "1"},         // 7th significant digit below 5: rounds down
      {1.0000051, "1.00001"},   // above 5: rounds up, trailing zeros dropped
      {0.12345649999, "0.123456"},
      {0.1234565001, "0.123457"},
      {0.1 + 0.2, "0.3"},
      {0.09999999999999999, "0.1"},  // the accumulated clock at step 10, dt 0.01
      {-9.31076, "-9.31076"},
      {std::numeric_limits<double>::max(), "1.79769e+308"},
      {std::numeric_limits<double>::denorm_min(), "4.94066e-324"},
      {-std::numeric_limits<double>::min(), "-2.22507e-308"},
  };
  for (const auto& row : table) {
    EXPECT_EQ(format_g6(row.value), row.text) << "value " << printf_g6(row.value);
  }
}

TEST(FormatG6, AgreesWithPrintfOnRandomValues) {
  // Random bit patterns cover every exponent, subnormals, NaNs and infinities.
  std::mt19937_64 rng(42);
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    ASSERT_EQ(format_g6(x), printf_g6(x)) << "bits " << bits;
  }
  // Values of ordinary magnitude with many digits, where rounding matters most.
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = uniform(rng);
    ASSERT_EQ(format_g6(x), printf_g6(x));
  }
}

TEST(FormatG6, AppendAddsToExistingText) {
  std::string out = "X=";
  append_g6(out, -0.5);
  append_g6(out, 2e-7);
  EXPECT_EQ(out, "X=-0.52e-07");
}

TEST(RoundG6, RoundsToSixSignificantDigits) {
  EXPECT_EQ(round_g6(1.23456789), 1.23457);
  EXPECT_EQ(round_g6(-0.97925949), -0.979259);
  EXPECT_EQ(round_g6(0.09999999999999999), 0.1);
  EXPECT_EQ(round_g6(2.775557561562891e-17), 2.77556e-17);
  EXPECT_EQ(round_g6(123456789.0), 123457000.0);
  EXPECT_EQ(round_g6(0.0), 0.0);
  EXPECT_TRUE(std::signbit(round_g6(-0.0)));
  EXPECT_EQ(round_g6(std::numeric_limits<double>::denorm_min()), 4.94066e-324);
  EXPECT_TRUE(std::isnan(round_g6(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(round_g6(-std::numeric_limits<double>::infinity()),
            -std::numeric_limits<double>::infinity());
}

TEST(RoundG6, IsIdempotentAndPreservesText) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    const double r = round_g6(x);
    ASSERT_EQ(round_g6(r), r) << printf_g6(x);
    ASSERT_EQ(format_g6(r), format_g6(x)) << printf_g6(x);
    // The rounding error is at most half a unit of the 6th significant digit.
    ASSERT_LE(std::fabs(r - x), 5.0000001e-6 * std::fabs(x)) << printf_g6(x);
  }
}

}  // namespace
}  // namespace sinew::regression
