// Issue 9: "contacts created and removed every step without per-step
// allocation once warm". Steady contact (a sheet of points and triangles
// resting on a fixed sheet, penalty contacts solved implicitly): once the
// set of colliding pairs is settled, whole steps (detection, contacts,
// solve) do not touch the heap.
#include <gtest/gtest.h>

#include "alloc_counter.h"
#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(CollisionAllocation, SteadyContactStepsDoNotAllocate) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "no allocation counter under AddressSanitizer";
  for (const char* method : {"MinProximityIntersection", "NewProximityIntersection", "LocalMinDistance"}) {
    const std::string xml = std::string(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
      <CollisionPipeline depth="8"/><BruteForceBroadPhase/><BVHNarrowPhase/>
      <)") + method + R"( alarmDistance="0.3" contactDistance="0.2"/>
      <CollisionResponse response="PenalityContactForceField"/>
      <Node name="floor">
        <RegularGridTopology n="8 1 8" min="0 0 0" max="3.5 0 3.5"/>
        <MechanicalObject/>
        <TriangleCollisionModel simulated="0" moving="0"/><LineCollisionModel simulated="0" moving="0"/>
        <PointCollisionModel simulated="0" moving="0"/>
      </Node>
      <Node name="sheet">
        <EulerImplicitSolver rayleighMass="1"/><CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-14"/>
        <RegularGridTopology n="6 1 6" min="0.6 0.25 0.7" max="2.6 0.25 2.7"/>
        <MechanicalObject/><UniformMass totalMass="1"/>
        <MeshSpringForceField stiffness="100"/>
        <TriangleCollisionModel/><LineCollisionModel/><PointCollisionModel/>
      </Node>
    </Node>)";
    scene::LoadedScene s = test::load(xml);
    ASSERT_TRUE(s.root);
    const long first = test::g_allocations.load();
    animate(*s.root);  // the first contacts are created: the counter sees it
    EXPECT_GT(test::g_allocations.load() - first, 0) << method;
    for (int i = 0; i < 300; ++i) animate(*s.root);  // settled on the floor
    long total = 0;
    for (int i = 0; i < 20; ++i) {
      const long before = test::g_allocations.load();
      animate(*s.root);
      total += test::g_allocations.load() - before;
    }
    EXPECT_EQ(total, 0) << method;
    std::size_t contacts = 0;
    for (ForceField* ff : s.root->find_child_named("sheet")->interaction_force_fields) contacts += ff->states().size();
    EXPECT_GT(contacts, 0u) << method << ": the sheet must be in contact";
  }
}

}  // namespace
}  // namespace sinew
