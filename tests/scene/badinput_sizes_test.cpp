// Bad-input hardening, sizes: a state size or a grid resolution that would
// not fit in memory is an error naming the component and the field, never
// std::bad_alloc.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class BadInputSizes : public ::testing::Test {
 protected:
  TempDir dir;
};

std::string with_root(const std::string& body, const std::string& root_attrs = R"(dt="0.01")") {
  return "<Node name=\"root\" " + root_attrs + ">\n  <DefaultAnimationLoop/>\n" + body + "\n</Node>\n";
}

}  // namespace

TEST_F(BadInputSizes, HugeStateSizeIsAnErrorNamingTheField) {
  const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" size="1000000000"/>)"));
  EXPECT_TRUE(o.loaded);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"'dofs' (MechanicalObject)", "'size' = 1000000000", "more than this machine"}))
      << o.all();
}

TEST_F(BadInputSizes, HugeGridIsAnErrorNamingTheField) {
  const Outcome o = run_xml(dir, with_root(R"(  <RegularGridTopology name="grid" n="5000 5000 5000" min="0 0 0" max="1 1 1"/>
  <MechanicalObject name="dofs"/>)"));
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {"'grid' (RegularGridTopology)", "'n' = 5000 5000 5000"})) << o.all();
  const Outcome w = run_xml(dir, with_root(R"(  <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" cellWidth="1e-7"/>
  <MechanicalObject name="dofs"/>)"));
  EXPECT_FALSE(w.init_ok);
  EXPECT_TRUE(any_contains_all(w.errors, {"'grid' (RegularGridTopology)", "'cellWidth'"})) << w.all();
  const Outcome s = run_xml(dir, with_root(R"(  <CubeTopology name="cube" nx="100000" ny="100000" nz="100000"/>
  <MechanicalObject name="dofs"/>)"));
  EXPECT_FALSE(s.init_ok);
  EXPECT_TRUE(any_contains_all(s.errors, {"'cube' (CubeTopology)", "'nx ny nz'"})) << s.all();
}
