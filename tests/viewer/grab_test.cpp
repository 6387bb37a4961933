// Picking and the mouse spring (SOFA's AttachBody) on real scenes, without a window.
#include <gtest/gtest.h>

#include <regex>

#include "collision/collision_model.h"
#include "core/node.h"
#include "render/draw_list.h"
#include "runner/session.h"
#include "test_scene.h"
#include "viewer/mouse_attach.h"
#include "viewer/picking.h"
#include "test_paths.h"

namespace sinew::viewer {
namespace {

std::string grab_scene_text() {
  std::ifstream in(std::string(SINEW_SOURCE_DIR) + "/tests/viewer/grab_cube.scn");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void step(Node& root, int n) {
  for (int i = 0; i < n; ++i) animate(root);
}

int count_nodes(Node& root) {
  int n = 0;
  for_each_node(root, [&](Node&) { ++n; });
  return n;
}

TEST(Picking, RayAgainstTrianglesAndSpheres) {
  Ray r;
  r.origin = Vec3(0.2, 0.2, 5);
  r.dir = Vec3(0, 0, -1);
  EXPECT_NEAR(ray_triangle(r, Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)), 4.0, 1e-12);
  EXPECT_LT(ray_triangle(r, Vec3(1, 1, 1), Vec3(2, 1, 1), Vec3(1, 2, 1)), 0);  // beside
  EXPECT_LT(ray_triangle(r, Vec3(0, 0, 6), Vec3(1, 0, 6), Vec3(0, 1, 6)), 0);  // behind
  EXPECT_NEAR(ray_sphere(r, Vec3(0.2, 0.2, 0), 1.0), 4.0, 1e-12);
  r.origin = Vec3(0.2, 0.2, 0);  // inside: the exit point
  EXPECT_NEAR(ray_sphere(r, Vec3(0.2, 0.2, 0), 1.0), 1.0, 1e-12);
  EXPECT_LT(ray_sphere(r, Vec3(5, 5, 0), 1.0), 0);
}

TEST(Picking, FindsTheCollisionTriangleInFront) {
  auto s = test::load(grab_scene_text());
  ASSERT_TRUE(s.root);
  step(*s.root, 1);  // the collision models are up to date after a step
  Ray r;
  r.origin = Vec3(0.1, 0.3, 5);
  r.dir = Vec3(0, 0, -1);
  render::DrawList none;
  const Pick p = pick(*s.root, none, r, 0.1);
  ASSERT_EQ(p.on, Pick::On::collision_element);
  EXPECT_NEAR(p.distance, 4.0, 1e-9);  // the front face z = 1, not the back one
  EXPECT_NEAR((p.point - Vec3(0.1, 0.3, 1)).norm(), 0.0, 1e-9);
  r.origin = Vec3(3, 3, 5);
  EXPECT_FALSE(pick(*s.root, none, r, 0.1));
}

// Grabs the front face's centre and pulls it up by 0.5 for 100 steps of 0.02 s.
void pull(Node& root, MouseAttach& attach, Vec3& start, Vec3& end) {
  step(root, 1);
  Ray r;
  r.origin = Vec3(0, 0, 5);
  r.dir = Vec3(0, 0, -1);
  render::DrawList none;
  const Pick p = pick(root, none, r, 0.1);
  ASSERT_EQ(p.on, Pick::On::collision_element);
  std::string why;
  ASSERT_TRUE(attach.start(p, 1000, &why)) << why;
  start = attach.attached_point();
  EXPECT_NEAR((start - Vec3(0, 0, 1)).norm(), 0.0, 1e-9);
  attach.move(start + Vec3(0, 0.5, 0));
  step(root, 100);
  end = attach.attached_point();
}

TEST(MouseAttach, PullsTheGrabbedPointTowardsTheMouseAndLetsGo) {
  auto s = test::load(grab_scene_text());
  ASSERT_TRUE(s.root);
  Node& root = *s.root;
  const int nodes = count_nodes(root);
  MouseAttach attach;
  Vec3 start, end;
  pull(root, attach, start, end);
  // SOFA's "AttachedPoint" node under the collision model, and the spring in it.
  EXPECT_EQ(count_nodes(root), nodes + 1);
  Node* surface = root.find_child_named("cube")->find_child_named("surface");
  Node* mapped = surface->find_child_named("AttachedPoint");
  ASSERT_NE(mapped, nullptr);
  EXPECT_NE(mapped->find_object_named("Spring-Mouse-Contact"), nullptr);
  // Towards the cursor: mostly up, and held back by the elastic cube.
  EXPECT_GT(end[1], 0.25);
  EXPECT_LT(end[1], 0.5);
  EXPECT_NEAR(end[0], 0.0, 1e-3);  // the face's triangulation is not symmetric about x = 0
  EXPECT_LT((end - attach.target()).norm(), 0.25);

  attach.stop();
  EXPECT_EQ(count_nodes(root), nodes);
  // The body springs back once released.
  const auto& x = root.find_child_named("cube")->mechanical_state->read(kPosition);
  double top = 0;
  for (std::size_t i = 0; i < x.size(); i += 3) top = std::max(top, x[i + 1]);
  step(root, 300);
  double top_after = 0;
  for (std::size_t i = 0; i < x.size(); i += 3) top_after = std::max(top_after, x[i + 1]);
  EXPECT_GT(top, 1.1);
  EXPECT_NEAR(top_after, 1.0, 0.02);
}

TEST(MouseAttach, AssembledDirectSolverGivesTheSameDrag) {
  // The spring's stiffness goes through the mapped state's assembly (J^T K J).
  std::string text = grab_scene_text();
  text = std::regex_replace(text, std::regex("<CGLinearSolver[^>]*/>"),
                            "<SparseLDLSolver template=\"CompressedRowSparseMatrixMat3x3d\"/>");
  auto cg = test::load(grab_scene_text());
  auto ldl = test::load(text);
  ASSERT_TRUE(cg.root && ldl.root);
  MouseAttach a1, a2;
  Vec3 s1, e1, s2, e2;
  pull(*cg.root, a1, s1, e1);
  pull(*ldl.root, a2, s2, e2);
  // CG stops at its tolerance each step; over 100 steps the two differ by a few 1e-6.
  EXPECT_NEAR((e1 - e2).norm(), 0.0, 1e-5);
  EXPECT_GT(e2[1], 0.25);
}

TEST(MouseAttach, SpringForceAndStiffness) {
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject name="dofs" position="0 0 0  1 2 3"/>
    </Node>)");
  ASSERT_TRUE(s.root);
  MechanicalState& st = *s.root->mechanical_state;
  MouseSpring spring(st, 1, 50);
  spring.set_target(Vec3(1, 3, 1));
  st.write(kForce).assign(6, 0.0);
  spring.add_force(MechParams{});
  const auto& f = st.read(kForce);
  EXPECT_EQ(f[3], 0.0);
  EXPECT_EQ(f[4], 50.0);
  EXPECT_EQ(f[5], -100.0);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_DOUBLE_EQ(*spring.potential_energy(), 0.5 * 50 * 5);
  st.write(kDx).assign({0, 0, 0, 0.1, 0.2, 0.3});
  st.write(kDforce).assign(6, 0.0);
  spring.add_dforce(MechParams{}, 2.0);
  const auto& df = st.read(kDforce);
  EXPECT_DOUBLE_EQ(df[3], -2.0 * 50 * 0.1);
  EXPECT_DOUBLE_EQ(df[5], -2.0 * 50 * 0.3);
}

TEST(Picking, WithoutCollisionModelsTheVisibleSurfaceGivesTheNearestParticle) {
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
      <Node name="body">
        <EulerImplicitSolver/>
        <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>
        <RegularGridTopology name="grid" n="3 3 3" min="-1 -1 -1" max="1 1 1"/>
        <MechanicalObject name="dofs"/>
        <UniformMass totalMass="1"/>
        <Node name="visual">
          <OglModel name="skin" src="@../grid"/>
          <IdentityMapping/>
        </Node>
      </Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  render::DrawList list;
  render::gather(*s.root, list);
  Ray r;
  r.origin = Vec3(0.9, 0.1, 5);
  r.dir = Vec3(0, 0, -1);
  const Pick p = pick(*s.root, list, r, 0.1);
  ASSERT_EQ(p.on, Pick::On::particle);
  const auto& x = p.state->read(kPosition);
  // The grid point (1, 0, 1) is the nearest to the surface point (0.9, 0.1, 1).
  EXPECT_EQ(Vec3(&x[3 * p.index]), Vec3(1, 0, 1));
  EXPECT_NEAR(p.distance, 4.0, 1e-6);
  // Nothing drawn there, yet a particle within the tolerance of the ray is found: of the
  // three as close to the ray, the one nearest to the camera (SOFA's particle picking).
  render::DrawList none;
  r.origin = Vec3(1.05, 1.0, 5);
  const Pick q = pick(*s.root, none, r, 0.1);
  ASSERT_EQ(q.on, Pick::On::particle);
  EXPECT_EQ(Vec3(&q.state->read(kPosition)[3 * q.index]), Vec3(1, 1, 1));
}

}  // namespace
}  // namespace sinew::viewer
