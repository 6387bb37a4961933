// DistanceFromTargetMapping and SquareMapping on hand-computed values (SOFA's
// Sofa.Component.Mapping.NonLinear): outputs, J, Jᵀ, geometric stiffness and
// SOFA's init rules (indices completed from the targets, rest lengths padded
// with 0). The conformance battery checks J and the geometric stiffness against
// finite differences.
#include <gtest/gtest.h>

#include <vector>

#include "mapping/nonlinear/distance_from_target_mapping.h"
#include "mapping/nonlinear/square_mapping.h"
#include "test_scene.h"

namespace sinew {
namespace {

struct Setup {
  scene::LoadedScene s;
  MechanicalState* in = nullptr;
  MechanicalState* out = nullptr;
  Mapping* map = nullptr;
};

Setup make(const std::string& in_attrs, const std::string& cls, const std::string& map_attrs) {
  Setup r;
  r.s = test::load("<Node name='root' gravity='0 0 0'><MechanicalObject name='in' " + in_attrs +
                   "/><Node name='child'><MechanicalObject name='out' template='Vec1d'/><" + cls + " name='map' " +
                   map_attrs + "/></Node></Node>");
  if (!r.s.root) return r;
  Node& child = *r.s.root->find_child_named("child");
  r.in = test::get<MechanicalState>(*r.s.root, "in");
  r.out = test::get<MechanicalState>(child, "out");
  r.map = test::get<Mapping>(child, "map");
  return r;
}

// Errors reported while building and initialising `xml`.
std::vector<std::string> init_errors(const std::string& xml) {
  auto s = test::build(xml);
  if (!s.root) return {"not built"};
  init_root(*s.root);
  return test::messages(s.root->diagnostics(), Severity::error);
}

TEST(DistanceFromTargetMapping, DistancesDirectionsAndSofasDefaults) {
  // Point 1 sits on its target (degenerate: u = e0, no stiffness); point 0 is 5 from the origin.
  auto e = make("position='3 4 0  1 1 1'", "DistanceFromTargetMapping",
                "indices='1 0' targetPositions='1 1 1  0 0 0' restLengths='0.5'");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  auto* m = dynamic_cast<DistanceFromTargetMapping*>(e.map);
  ASSERT_NE(m, nullptr);
  // restLengths padded with 0 (the distance itself), not with the initial distance.
  EXPECT_EQ(m->rest_lengths.get(), (std::vector<double>{0.5, 0.0}));
  ASSERT_EQ(e.out->size(), 2u);
  EXPECT_DOUBLE_EQ(e.out->read(kPosition)[0], -0.5);
  EXPECT_DOUBLE_EQ(e.out->read(kPosition)[1], 5.0);
  const std::vector<double> u = {1, 0, 0, 0.6, 0.8, 0};
  for (std::size_t k = 0; k < u.size(); ++k) EXPECT_NEAR(m->directions()[k], u[k], 1e-15) << k;

  // J·dx: row 0 reads point 1's x, row 1 projects point 0's motion on (0.6, 0.8, 0).
  e.in->write(kDx) = {1, 2, 3, 4, 5, 6};
  m->apply_j(kDx, kDx);
  EXPECT_DOUBLE_EQ(e.out->read(kDx)[0], 4.0);
  EXPECT_DOUBLE_EQ(e.out->read(kDx)[1], 0.6 * 1 + 0.8 * 2);
  // Jᵀ·f added to the input forces.
  e.in->write(kForce) = {1, 1, 1, 0, 0, 0};
  e.out->write(kForce) = {2, -1};
  m->apply_jt(kForce, kForce);
  const std::vector<double> f = e.in->read(kForce);
  EXPECT_DOUBLE_EQ(f[0], 1 - 0.6);
  EXPECT_DOUBLE_EQ(f[1], 1 - 0.8);
  EXPECT_DOUBLE_EQ(f[2], 1.0);
  EXPECT_DOUBLE_EQ(f[3], 2.0);
  EXPECT_DOUBLE_EQ(f[4], 0.0);

  // Stabilized (default): only the stretched point (λ = −2 < 0) gets (I − u uᵀ)·λ/d.
  e.out->write(kForce) = {3, -2};
  e.in->write(kDx) = {1, 0, 1, 7, 7, 7};
  e.in->write(kDforce) = std::vector<double>(6, 0.0);
  m->apply_djt(kDforce, kDx, 1.0);
  const std::vector<double> df = e.in->read(kDforce);
  EXPECT_NEAR(df[0], 0.64 * -0.4, 1e-15);
  EXPECT_NEAR(df[1], -0.48 * -0.4, 1e-15);
  EXPECT_NEAR(df[2], -0.4, 1e-15);
  EXPECT_EQ(df[3], 0.0);
  EXPECT_EQ(df[5], 0.0);
}

TEST(DistanceFromTargetMapping, MissingIndicesAreTheTargetNumbers) {
  auto e = make("position='0 0 0  1 0 0  0 2 0'", "DistanceFromTargetMapping", "targetPositions='0 0 0  0 0 0  0 0 0'");
  auto* m = dynamic_cast<DistanceFromTargetMapping*>(e.map);
  ASSERT_TRUE(m && m->state() == ComponentState::valid);
  EXPECT_EQ(m->indices.get(), (std::vector<unsigned>{0, 1, 2}));
  EXPECT_EQ(e.out->read(kPosition), (std::vector<double>{0, 1, 2}));
}

TEST(DistanceFromTargetMapping, Rigid3dUsesTheCentreAndAddsSofasRotationStiffness) {
  auto e = make("template='Rigid3d' position='0 3 4 0 0 0.6 0.8'", "DistanceFromTargetMapping",
                "geometricStiffness='Exact' targetPositions='0 0 0 0 0 0 1'");
  auto* m = dynamic_cast<DistanceFromTargetMapping*>(e.map);
  ASSERT_TRUE(m && m->state() == ComponentState::valid);
  EXPECT_DOUBLE_EQ(e.out->read(kPosition)[0], 5.0);
  const std::vector<double> u = {0, 0.6, 0.8, 0, 0, 0};
  for (std::size_t k = 0; k < u.size(); ++k) EXPECT_NEAR(m->directions()[k], u[k], 1e-15) << k;
  // SOFA's 6×6 (I − u uᵀ)·λ/d: λ/d on the rotation diagonal although J ignores rotations.
  e.out->write(kForce) = {5};
  e.in->write(kDx) = {0, 0, 0, 1, 2, 3};
  e.in->write(kDforce) = std::vector<double>(6, 0.0);
  m->apply_djt(kDforce, kDx, 1.0);
  EXPECT_EQ(e.in->read(kDforce), (std::vector<double>{0, 0, 0, 1, 2, 3}));
}

TEST(DistanceFromTargetMapping, BadInputIsRefusedWithTheReason) {
  const std::string head = "<Node name='root'><MechanicalObject name='in' position='0 0 0  1 0 0'/><Node name='c'>"
                           "<MechanicalObject template='Vec1d'/>";
  auto errors = init_errors(head + "<DistanceFromTargetMapping indices='5' targetPositions='0 0 0'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "indices[0] = 5 but the input has 2 points")) << errors.size();
  errors = init_errors(head + "<DistanceFromTargetMapping indices='0 1' targetPositions='0 0 0'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "indices has 2 entries but targetPositions has 1"));
  errors = init_errors(head + "<DistanceFromTargetMapping targetPositions='0 0 0' geometricStiffness='Soft'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "geometricStiffness must be None, Exact or Stabilized"));
}

TEST(SquareMapping, SquaresItsDerivativesAndGeometricStiffness) {
  auto e = make("template='Vec1d' position='3 -0.5'", "SquareMapping", "");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  EXPECT_EQ(e.out->read(kPosition), (std::vector<double>{9, 0.25}));
  e.in->write(kDx) = {1, 2};
  e.map->apply_j(kDx, kDx);
  EXPECT_EQ(e.out->read(kDx), (std::vector<double>{6, -2}));
  e.in->write(kForce) = {0, 0};
  e.out->write(kForce) = {1, 1};
  e.map->apply_jt(kForce, kForce);
  EXPECT_EQ(e.in->read(kForce), (std::vector<double>{6, -1}));
  // Exact by default: df = 2·λ·k·dx, whatever the sign of λ.
  e.out->write(kForce) = {2, -1};
  e.in->write(kDx) = {1, 1};
  e.in->write(kDforce) = {0, 0};
  e.map->apply_djt(kDforce, kDx, 0.5);
  EXPECT_EQ(e.in->read(kDforce), (std::vector<double>{2, -1}));
  // The output follows the input's size at every apply.
  e.in->resize(3);
  e.in->write(kPosition)[2] = 4;
  e.map->apply(kPosition);
  EXPECT_EQ(e.out->read(kPosition), (std::vector<double>{9, 0.25, 16}));
}

TEST(SquareMapping, OffersNoStabilizedGeometricStiffness) {
  const auto errors = init_errors(
      "<Node name='root'><MechanicalObject template='Vec1d' position='1'/><Node name='c'>"
      "<MechanicalObject template='Vec1d'/><SquareMapping geometricStiffness='Stabilized'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "geometricStiffness must be None or Exact"));
}

}  // namespace
}  // namespace sinew
