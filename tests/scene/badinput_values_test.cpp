// Bad-input hardening, values: vector values of the wrong count are warned,
// huge attribute values are shortened in messages.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class BadInputValues : public ::testing::Test {
 protected:
  TempDir dir;
};

std::string with_root(const std::string& body, const std::string& root_attrs = R"(dt="0.01")") {
  return "<Node name=\"root\" " + root_attrs + ">\n  <DefaultAnimationLoop/>\n" + body + "\n</Node>\n";
}

}  // namespace

TEST_F(BadInputValues, VectorValuesOfTheWrongCountAreWarned) {
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0"/>
  <UniformMass totalMass="1"/>
  <ConstantForceField name="cf" forces="1 2" indices="0"/>
  <MeshTopology name="topo" edges="0 1 2"/>)", R"(dt="0.01" gravity="0 -9.81")"));
  EXPECT_TRUE(any_contains_all(o.warnings, {"node 'root'", "field 'gravity'", "expected 3 values (Vec3d), got 2"}))
      << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'dofs' (MechanicalObject)", "field 'position'",
                                            "expected a multiple of 3 values", "got 8"}))
      << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'cf' (ConstantForceField)", "field 'forces'", "got 2"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'topo' (MeshTopology)", "field 'edges'", "multiple of 2"})) << o.all();
}

TEST_F(BadInputValues, RightVectorCountsAreNotWarned) {
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0 1 0 0"/>
  <UniformMass totalMass="1"/>)", R"(dt="0.01" gravity="0 -9.81 0")"));
  EXPECT_FALSE(any_contains(o.warnings, "expected")) << o.all();
}

TEST_F(BadInputValues, HugeValuesAreShortenedInMessages) {
  const std::string big(5'000'000, 'x');
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass totalMass=")" + big + R"(" bogus=")" + big + R"("/>)"));
  ASSERT_FALSE(o.problems().empty());
  std::size_t total = 0;
  for (const auto& m : o.problems()) total += m.size();
  EXPECT_LT(total, 10'000u) << "messages echo the whole value";
  EXPECT_TRUE(any_contains_all(o.warnings, {"totalMass", "(5000000 characters)"})) << o.all().substr(0, 2000);
  EXPECT_TRUE(any_contains_all(o.warnings, {"unused attribute 'bogus'", "(5000000 characters)"}))
      << o.all().substr(0, 2000);
}
