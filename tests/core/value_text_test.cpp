// Values quoted in messages (shortened) and value counts of vector fields.
#include <gtest/gtest.h>

#include <string>

#include "core/base.h"
#include "core/field.h"
#include "core/value_text.h"

using namespace sinew;

namespace {

class Owner final : public Base {
 public:
  explicit Owner(std::string n) : n_(std::move(n)) {}
  std::string describe() const override { return "owner '" + n_ + "'"; }

 private:
  std::string n_;
};

}  // namespace

TEST(ValueText, LongValuesAreShortened) {
  EXPECT_EQ(quote_value("abc"), "\"abc\"");
  const std::string big(1'000'000, 'y');
  const std::string q = quote_value(big);
  EXPECT_LT(q.size(), 140u);
  EXPECT_NE(q.find("…\" (1000000 characters)"), std::string::npos) << q;
}

TEST(ValueText, CountsOfVectorValues) {
  Owner o("o");
  Field<Vec3> g(&o, "gravity", Vec3::Zero(), "");
  Field<std::vector<Vec3>> x(&o, "position", {}, "");
  Field<std::vector<std::array<unsigned, 2>>> e(&o, "edges", {}, "");
  Field<double> s(&o, "scalar", 0, "");
  EXPECT_EQ(value_count_problem(g, "0 -9.81 0"), "");
  EXPECT_NE(value_count_problem(g, "0 -9.81").find("expected 3 values (Vec3d), got 2"), std::string::npos);
  EXPECT_NE(value_count_problem(g, "0 0 0 1").find("got 4"), std::string::npos);
  EXPECT_EQ(value_count_problem(x, "0 0 0 1 1 1"), "");
  EXPECT_NE(value_count_problem(x, "0 0 0 1").find("multiple of 3"), std::string::npos);
  EXPECT_NE(value_count_problem(e, "0 1 2").find("multiple of 2"), std::string::npos);
  EXPECT_EQ(value_count_problem(s, "1 2"), "");
}
