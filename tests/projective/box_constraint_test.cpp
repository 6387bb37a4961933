// BoxConstraint (spec/mechanics.md §0.8): not a class in SOFA but the XML macro
// examples/Objects/BoxConstraint.xml (a BoxROI feeding a FixedProjectiveConstraint),
// expanded in place with the element's attributes; the points inside one of the boxes
// stay fixed over the steps while the others fall.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/simulation.h"
#include "engine/box_roi.h"
#include "projective/fixed_projective_constraint.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;
namespace fs = std::filesystem;

TEST(BoxConstraint, MacroFixesThePointsInsideTheBoxesOverSteps) {
  const fs::path examples = fs::path(SINEW_DATA_DIR) / "examples";
  if (!fs::exists(examples / "Objects/BoxConstraint.xml")) GTEST_SKIP() << "SOFA data not found at " << examples;
  register_all_components();
  test::TempDir dir;
  // A 4×2×2 grid of free points, x in [0, 3]: the two boxes hold the x = 0 and x = 3 faces.
  const std::string file = dir.write("box.scn", R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-12"/>
    <RegularGridTopology name="grid" nx="4" ny="2" nz="2" xmin="0" xmax="3" ymin="0" ymax="1" zmin="0" zmax="1"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="1"/>
    <BoxConstraint box="-0.1 -0.1 -0.1  0.1 1.1 1.1   2.9 -0.1 -0.1  3.1 1.1 1.1"/>
  </Node>)");
  scene::LoadOptions opts;
  opts.data_paths = {examples.string()};
  opts.use_sofa_data_path = false;
  Diagnostics diag;
  scene::LoadedScene s = scene::load_scene(file, opts, diag);
  ASSERT_TRUE(s.root);
  ASSERT_TRUE(s.ok()) << (s.root->diagnostics().messages().empty()
                              ? std::string()
                              : Diagnostics::format(s.root->diagnostics().messages().front()));
  EXPECT_TRUE(s.missing.empty());
  init_root(*s.root);
  auto* roi = test::get<BoxROI>(*s.root, "box_roi");
  ASSERT_TRUE(roi);
  // Grid order: x fastest, then y, then z.
  const std::vector<unsigned> fixed = {0, 3, 4, 7, 8, 11, 12, 15};
  EXPECT_EQ(roi->indices.get(), fixed);
  FixedProjectiveConstraint* fix = nullptr;
  for (Component* c : s.root->projective_constraints) fix = fix ? fix : dynamic_cast<FixedProjectiveConstraint*>(c);
  ASSERT_TRUE(fix);
  EXPECT_EQ(fix->indices.get(), fixed);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  ASSERT_TRUE(mo);
  const std::vector<double> x0 = mo->read(kPosition);
  for (int step = 0; step < 20; ++step) animate(*s.root);
  const std::vector<double>& x = mo->read(kPosition);
  for (unsigned i = 0; i < 16; ++i) {
    const bool in = std::find(fixed.begin(), fixed.end(), i) != fixed.end();
    if (in) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(x[3 * i + c], x0[3 * i + c]) << i;
    } else {
      EXPECT_LT(x[3 * i + 1], x0[3 * i + 1] - 0.01) << i;  // fell (free fall: about 0.2 after 0.2 s)
    }
  }
}
