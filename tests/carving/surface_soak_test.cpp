// Soak (issue 11): a simulated cloth of 800 triangles with a mapped collision model resting on
// a floor loses one random triangle at a time until it is empty. After every removal nothing
// dangles: the shells agree with the lists, the state, the mapped collision state and the mass
// have one entry per point; every few removals a step runs (collision included) and the state
// stays finite, the collision models holding exactly the remaining elements.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "collision/model/point_collision_model.h"
#include "collision/narrow_phase.h"
#include "collision/model/triangle_collision_model.h"
#include "core/simulation.h"
#include "mass/diagonal_mass.h"
#include "projective/fixed_projective_constraint.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/element_removal.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {
namespace {

using test::get;

// A 1 × 1 square of 20 × 20 cells, two triangles each, as a triangle container's own lists.
std::string cloth_mesh() {
  std::string pos, tris;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) pos += std::to_string(i / 20.0) + " " + std::to_string(j / 20.0) + " 0 ";
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const int a = i + 21 * j, b = a + 1, c = a + 22, d = a + 21;
      tris += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " ";
      tris += std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + " ";
    }
  return "<MechanicalObject name=\"dofs\" position=\"" + pos + "\"/>\n" +
         "<TriangleSetTopologyContainer name=\"tris\" triangles=\"" + tris + "\"/>\n";
}

TEST(SurfaceSoak, RandomTriangleRemovalWithAMappedCollisionModel) {
  auto s = test::load(std::string(R"(<Node gravity="0 0 -9.81" dt="0.01">
    <CollisionPipeline/>
    <BruteForceBroadPhase/>
    <BVHNarrowPhase/>
    <CollisionResponse response="PenalityContactForceField"/>
    <MinProximityIntersection alarmDistance="0.05" contactDistance="0.01"/>
    <Node name="cloth">
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
      <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>
      )") + cloth_mesh() + R"(
      <TriangleSetTopologyModifier name="mod"/>
      <DiagonalMass name="mass" massDensity="1"/>
      <FixedProjectiveConstraint name="fix" indices="0 20 420 440"/>
      <TriangularFEMForceField youngModulus="500" poissonRatio="0.3" method="large"/>
      <Node name="collision">
        <MechanicalObject name="cdofs"/>
        <TriangleCollisionModel name="ctri"/>
        <PointCollisionModel name="cpoint"/>
        <IdentityMapping/>
      </Node>
    </Node>
    <Node name="floor">
      <MechanicalObject position="-1 -1 -0.05  2 -1 -0.05  2 2 -0.05  -1 2 -0.05"/>
      <MeshTopology triangles="0 1 2  0 2 3"/>
      <TriangleCollisionModel simulated="0" moving="0"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  Node& cloth = *s.root->find_child_named("cloth");
  Node& coll = *cloth.find_child_named("collision");
  auto& tris = *get<TriangleSetTopologyContainer>(cloth, "tris");
  auto& mod = *get<TriangleSetTopologyModifier>(cloth, "mod");
  auto& mo = *get<MechanicalObject>(cloth, "dofs");
  auto& cmo = *get<MechanicalObject>(coll, "cdofs");
  auto& mass = *get<DiagonalMass>(cloth, "mass");
  auto& fix = *get<FixedProjectiveConstraint>(cloth, "fix");
  auto& ctri = *get<TriangleCollisionModel>(coll, "ctri");
  auto& cpoint = *get<PointCollisionModel>(coll, "cpoint");
  ASSERT_EQ(tris.triangles().size(), 800u);
  for (int i = 0; i < 20; ++i) animate(*s.root);  // the cloth sags onto the floor first

  auto& narrow = *s.root->find_local<BVHNarrowPhase>();
  auto contacts = [&] {
    std::size_t n = 0;
    for (const auto& p : narrow.outputs()) n += p.outputs.size();
    return n;
  };
  std::mt19937 rng(5);
  std::size_t step = 0, steps_in_contact = 0;
  while (!tris.triangles().empty()) {
    const auto n = static_cast<unsigned>(tris.triangles().size());
    mod.remove_triangles({std::uniform_int_distribution<unsigned>(0, n - 1)(rng)}, true, true);
    ASSERT_EQ(tris.triangles().size(), n - 1u);
    ASSERT_EQ(topo::check_dynamic_mesh(tris.begin_edit()), "") << "after removal " << step;
    ASSERT_EQ(mo.size(), tris.nb_points());
    ASSERT_EQ(cmo.size(), tris.nb_points());
    ASSERT_EQ(mass.masses().size(), tris.nb_points());
    for (unsigned i : fix.indices.value()) ASSERT_LT(i, mo.size());
    if (step % 4 == 0) {
      animate(*s.root);
      steps_in_contact += contacts() > 0;
      ASSERT_EQ(ctri.size(), tris.triangles().size()) << "step " << step;
      ASSERT_EQ(cpoint.size(), tris.nb_points()) << "step " << step;
      for (double v : mo.read(kPosition)) ASSERT_TRUE(std::isfinite(v)) << "step " << step;
      for (std::size_t i = 0; i < cmo.size() * 3; ++i)
        ASSERT_EQ(cmo.read(kPosition)[i], mo.read(kPosition)[i]) << "mapped state out of step at " << step;
    }
    ++step;
  }
  animate(*s.root);
  EXPECT_GT(steps_in_contact, 100u);  // the cloth lay on the floor while it was cut
  EXPECT_EQ(mo.size(), 0u);
  EXPECT_EQ(cmo.size(), 0u);
  EXPECT_TRUE(tris.edges().empty());
}

}  // namespace
}  // namespace sinew
