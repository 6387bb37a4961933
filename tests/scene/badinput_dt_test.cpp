// Bad-input hardening: dt <= 0 (or not a number) on the root is refused at
// init (SOFA would not advance time).
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class BadInputDt : public ::testing::Test {
 protected:
  TempDir dir;
};

std::string with_root(const std::string& body, const std::string& root_attrs = R"(dt="0.01")") {
  return "<Node name=\"root\" " + root_attrs + ">\n  <DefaultAnimationLoop/>\n" + body + "\n</Node>\n";
}

}  // namespace

TEST_F(BadInputDt, ZeroOrNegativeDtIsRefused) {
  for (const char* dt : {"0", "-0.01", "nan"}) {
    const Outcome o = run_xml(dir, with_root(R"(  <MechanicalObject name="dofs" position="0 0 0"/>
  <UniformMass totalMass="1"/>)", std::string("dt=\"") + dt + "\""));
    EXPECT_FALSE(o.init_ok) << dt;
    EXPECT_TRUE(any_contains_all(o.errors, {"node 'root'", "dt = ", "must be a positive number"})) << dt << o.all();
  }
}
