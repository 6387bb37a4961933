// SOFA's IncisionTrianglesProcess.scn (Component/Topology/Container/Dynamic) run through its 22
// incisions that come due (T= 1.0 … 2.05; from T= 2.1 on, accumulated time drifts past each T=
// by one step and SOFA's saved-incision lookup, within 1e-10, misses them: warnings here, errors
// in SOFA, no cut in either). Checked after 230 steps: the counts, the Triangle2Edge output equal
// to the border edges, the state / DiagonalMass / FixedProjectiveConstraint following, every
// triangle oriented as at rest. Skipped without SOFA's data.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "badinput_helpers.h"
#include "mass/diagonal_mass.h"
#include "projective/fixed_projective_constraint.h"
#include "runner/session.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/edge_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "test_paths.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;
const fs::path kData = SINEW_DATA_DIR;
const char* kScene = "Component/Topology/Container/Dynamic/IncisionTrianglesProcess.scn";

Component* find(Node& n, std::string_view name) {
  for (const auto& o : n.objects())
    if (o->name.value() == name) return o.get();
  for (const auto& c : n.children())
    if (Component* r = find(*c, name)) return r;
  return nullptr;
}

TEST(TopologyIncisionScene, IncisionTrianglesProcessCutsAndEverythingFollows) {
  if (!fs::exists(kData / "examples" / kScene)) GTEST_SKIP() << "SOFA data not found at " << kData;
  runner::SessionOptions opts;
  opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
  runner::Session session((kData / "examples" / kScene).string(), opts);
  ASSERT_TRUE(session.ok());
  for (int i = 0; i < 230; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  EXPECT_TRUE(test::messages(session.diagnostics(), Severity::error).empty());
  EXPECT_TRUE(test::all_finite(session.root()));
  Node& root = session.root();
  auto& topo = dynamic_cast<TriangleSetTopologyContainer&>(*find(root, "Triangle_topo"));
  auto& edges = dynamic_cast<EdgeSetTopologyContainer&>(*find(root, "Edge_topo"));
  auto& mo = dynamic_cast<MechanicalObject&>(*find(root, "default4"));
  auto& mass = dynamic_cast<DiagonalMass&>(*find(root, "default5"));
  // From 774 points, 1450 triangles, 2223 edges (96 on the border).
  EXPECT_EQ(topo.nb_points(), 969u);
  EXPECT_EQ(topo.triangles().size(), 1626u);
  EXPECT_EQ(topo.edges().size(), 2595u);
  EXPECT_EQ(mo.size(), topo.nb_points());
  EXPECT_EQ(mass.masses().size(), topo.nb_points());
  // Triangle2EdgeTopologicalMapping: exactly the border edges, the lips of the cut included.
  std::map<std::pair<unsigned, unsigned>, int> uses;
  for (const Triangle& t : topo.triangles())
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::set<std::pair<unsigned, unsigned>> border, mapped;
  for (const auto& [e, n] : uses) {
    EXPECT_LE(n, 2);
    if (n == 1) border.insert(e);
  }
  for (const Edge& e : edges.edges()) mapped.insert(std::minmax(e[0], e[1]));
  EXPECT_EQ(border.size(), 312u);
  EXPECT_EQ(mapped, border);
  // Orientation and area at rest: the square of side 10, every triangle facing −z as the mesh
  // file's do.
  const auto& X0 = mo.read(kRestPosition);
  double area = 0;
  std::size_t up = 0;
  for (const Triangle& t : topo.triangles()) {
    const double z = (X0[3 * t[1]] - X0[3 * t[0]]) * (X0[3 * t[2] + 1] - X0[3 * t[0] + 1]) -
                     (X0[3 * t[1] + 1] - X0[3 * t[0] + 1]) * (X0[3 * t[2]] - X0[3 * t[0]]);
    up += z >= 0;
    area -= z / 2;
  }
  EXPECT_EQ(up, 0u);
  EXPECT_NEAR(area, 100.0, 1e-9);
  double total = 0;
  for (double m : mass.masses()) total += m;
  EXPECT_NEAR(total, 1.5 * 100.0, 1e-9);
  for (const char* name : {"fixedProjectiveConstraint1", "fixedProjectiveConstraint2"})
    for (unsigned i : dynamic_cast<FixedProjectiveConstraint&>(*find(root, name)).indices.value())
      EXPECT_LT(i, topo.nb_points());
}

}  // namespace
}  // namespace sinew
