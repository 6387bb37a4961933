// Findings of the mutated-scene campaign (scripts/mutate, docs/hardening.md), one test each.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

class BadInputMutations : public ::testing::Test {
 protected:
  TempDir dir;
};

}  // namespace

// scripts/mutate: a "link cycle" through pseudo-attributes (MechanicalObject's dx/ry,
// RegularGridTopology's xmin/zmin) ran silently: they are not fields, so the links were
// read as the number 0. They are not linkable (as in SOFA), and now say so; garbage in a
// pseudo-attribute is a warning too.
TEST_F(BadInputMutations, LinksAndGarbageInPseudoAttributesAreWarned) {
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <RegularGridTopology name="grid" nx="3" ny="@grid.nx" nz="3" xmin="@grid.zmin" xmax="1" ymin="0" ymax="1" zmin="@grid.xmin" zmax="abc"/>
  <MechanicalObject name="dofs" src="@grid" ry="@dofs.dx" dx="@dofs.ry" dz="1e400"/>
</Node>)",
                            1);
  EXPECT_TRUE(any_contains_all(o.warnings, {"scene.scn:3", "'grid' (RegularGridTopology)", "'xmin' is not a data field"}))
      << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'ny' is not a data field"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"could not read a number for 'zmax'", "\"abc\""})) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"scene.scn:4", "'dofs' (MechanicalObject)", "'ry' is not a data field"}))
      << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"could not read a number for 'dz'", "1e400"})) << o.all();
}
