// ClusteringEngine, ShapeMatching and PositionBasedDynamicsProjectiveConstraint: clusters of a
// polyline by hand (geodesic and straight-line), shape-matching targets of moved and stretched
// shapes, one projection by hand, and SOFA's dragon keeping its shape as it falls.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <filesystem>

#include "badinput_helpers.h"
#include "engine/analyze/clustering_engine.h"
#include "engine/analyze/shape_matching.h"
#include "runner/session.h"
#include "test_paths.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

using Clusters = std::vector<std::vector<unsigned>>;

// Five points on the x axis, joined in a line.
const char* kLine = "<MeshTopology name='topo' position='0 0 0  1 0 0  2 0 0  3 0 0  4 0 0' edges='0 1  1 2  2 3  3 4'/>";

// Root-mean-square distance between b and a moved rigidly onto it (Kabsch), over the points.
double rigid_fit_rms(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size() / 3;
  Eigen::MatrixXd A(n, 3), B(n, 3);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      A(static_cast<Eigen::Index>(i), c) = a[3 * i + c];
      B(static_cast<Eigen::Index>(i), c) = b[3 * i + c];
    }
  const Eigen::RowVector3d ca = A.colwise().mean(), cb = B.colwise().mean();
  A.rowwise() -= ca;
  B.rowwise() -= cb;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(A.transpose() * B, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  const Eigen::Matrix3d r = svd.matrixU() * d * svd.matrixV().transpose();
  return std::sqrt((A * r - B).rowwise().squaredNorm().mean());
}

}  // namespace

// Geodesic: centres 0 then 4 (farthest along the line); point 2, as far from both, stays in
// 0's cell (a tie does not move it). Each cluster is its cell plus one ring.
TEST(ClusteringEngine, LineClustersAlongTheEdges) {
  auto s = load(std::string("<Node>") + kLine +
                "<ClusteringEngine name='c' position='@topo.position' number='2' radius='0.1'/></Node>");
  auto* c = get<ClusteringEngine>(*s.root, "c");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->cluster.get(), (Clusters{{0, 1, 2, 3}, {4, 3, 2}}));
}

// Straight-line distances: a point near no other centre joins the nearest other one, even a
// centre (SOFA's rule: no point is left without a cluster).
TEST(ClusteringEngine, WithoutTopologyRadiusThenNearestCentre) {
  auto s = load(std::string("<Node>") + kLine +
                "<ClusteringEngine name='c' useTopo='0' position='@topo.position' number='2' radius='1.5'/></Node>");
  auto* c = get<ClusteringEngine>(*s.root, "c");
  EXPECT_EQ(c->cluster.get(), (Clusters{{0, 1, 2, 4}, {4, 0, 3}}));
  // number = -1: every point is a centre.
  auto all = load(std::string("<Node>") + kLine +
                  "<ClusteringEngine name='c' useTopo='0' position='@topo.position' radius='1.5'/></Node>");
  EXPECT_EQ(get<ClusteringEngine>(*all.root, "c")->cluster.get(),
            (Clusters{{0, 1}, {1, 0, 2}, {2, 1, 3}, {3, 2, 4}, {4, 3}}));
}

// One cluster of a tetrahedron: moved rigidly, the targets are the positions; stretched ×2
// about its centre, the rigid fit gives back the rest shape, the affine fit the positions.
TEST(ShapeMatching, TargetsKeepRigidMotionsAndUndoStretching) {
  const std::string rest = "1 0 0  0 2 0  0 0 3  -1 -2 -3";  // centre at the origin
  auto scene = [&](const std::string& positions, const std::string& extra) {
    return "<Node><MechanicalObject name='dofs' position='" + rest + "'/>"
           "<ShapeMatching name='sm' position='" + positions + "' cluster='4 0 1 2 3' " + extra + "/></Node>";
  };
  // A quarter turn about z then a shift.
  const std::vector<double> moved = {0 + 5, 1 + 6, 0 + 7, -2 + 5, 0 + 6, 0 + 7, 0 + 5, 0 + 6, 3 + 7, 2 + 5, -1 + 6, -3 + 7};
  std::string text;
  for (double v : moved) text += std::to_string(v) + " ";
  {
    auto s = load(scene(text, ""));
    const auto& t = get<ShapeMatching>(*s.root, "sm")->target_position.get().data;
    ASSERT_EQ(t.size(), 12u);
    for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(t[k], moved[k], 1e-12) << k;
  }
  {
    auto s = load(scene("2 0 0  0 4 0  0 0 6  -2 -4 -6", ""));
    const auto& t = get<ShapeMatching>(*s.root, "sm")->target_position.get().data;
    const std::vector<double> expected = {1, 0, 0, 0, 2, 0, 0, 0, 3, -1, -2, -3};
    for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(t[k], expected[k], 1e-12) << k;
  }
  {
    auto s = load(scene("2 0 0  0 4 0  0 0 6  -2 -4 -6", "affineRatio='1'"));
    const auto& t = get<ShapeMatching>(*s.root, "sm")->target_position.get().data;
    const std::vector<double> expected = {2, 0, 0, 0, 4, 0, 0, 0, 6, -2, -4, -6};
    for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(t[k], expected[k], 1e-12) << k;
  }
}

// x += k (target − x), v = (x − x_old)/dt with x_old the position at the previous projection.
TEST(PositionBasedDynamicsProjectiveConstraint, OneProjectionByHand) {
  auto s = load("<Node dt='0.1'><MechanicalObject name='dofs' position='0 0 0  1 1 1'/>"
                "<PositionBasedDynamicsProjectiveConstraint name='pbd' stiffness='0.5' position='1 0 0  1 3 1'/>"
                "</Node>");
  auto* pbd = dynamic_cast<ProjectiveConstraint*>(s.root->find_object_named("pbd"));
  ASSERT_NE(pbd, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  // Initialisation projects once (halfway); that projection had no earlier position.
  EXPECT_EQ(st.read(kPosition), (std::vector<double>{0.5, 0, 0, 1, 2, 1}));
  pbd->project_position(kPosition, 0.0);  // halfway again
  EXPECT_EQ(st.read(kPosition), (std::vector<double>{0.75, 0, 0, 1, 2.5, 1}));
  pbd->project_velocity(kVelocity, 0.0);
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_NEAR(st.read(kVelocity)[k], (std::vector<double>{2.5, 0, 0, 0, 5, 0})[k], 1e-12);
  pbd->project_position(kPosition, 0.0);
  EXPECT_EQ(st.read(kPosition), (std::vector<double>{0.875, 0, 0, 1, 2.75, 1}));
  pbd->project_velocity(kVelocity, 0.0);
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_NEAR(st.read(kVelocity)[k], (std::vector<double>{1.25, 0, 0, 0, 2.5, 0})[k], 1e-12);
}

// SOFA's example: 50 clusters over the dragon, which falls on the floor and keeps its shape.
TEST(ShapeMatching, SofaDragonFallsAndKeepsItsShape) {
  namespace fs = std::filesystem;
  const fs::path data = SINEW_DATA_DIR;
  const fs::path scene = data / "examples/Component/Engine/Analyze/ShapeMatching.scn";
  if (!fs::exists(scene)) GTEST_SKIP() << "SOFA data not found at " << data;
  runner::SessionOptions opts;
  opts.data_paths = {(data / "share").string(), (data / "examples").string()};
  runner::Session session(scene.string(), opts);
  ASSERT_TRUE(session.ok());
  Node* dragon = session.root().find_child_named("dragon");
  ASSERT_NE(dragon, nullptr);
  EXPECT_EQ(get<ClusteringEngine>(*dragon, "clustering")->cluster.get().size(), 50u);
  const std::vector<double> start = dragon->mechanical_state->read(kPosition);
  for (int i = 0; i < 40; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  // Falling freely (before it reaches the floor at step ~46) every cluster moves rigidly.
  EXPECT_LT(rigid_fit_rms(start, dragon->mechanical_state->read(kPosition)), 1e-9);
  for (int i = 40; i < 100; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  const std::vector<double>& x = dragon->mechanical_state->read(kPosition);
  EXPECT_TRUE(test::all_finite(session.root()));
  double ymin_start = 1e9, ymin = 1e9;
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    ymin_start = std::min(ymin_start, start[3 * i + 1]);
    ymin = std::min(ymin, x[3 * i + 1]);
  }
  EXPECT_LT(ymin, ymin_start - 2.0);  // it fell (gravity −1 for 5 s, the floor at −10)
  // On the floor the contacts bend it, the clusters hold it: its points stay within 5 % of the
  // dragon's size (23) of a rigid motion of the start (3.6 % measured).
  const double rms = rigid_fit_rms(start, x);
  EXPECT_GT(rms, 1e-3);
  EXPECT_LT(rms, 0.05 * 23.0);
  const auto errors = test::messages(session.diagnostics(), Severity::error);
  EXPECT_TRUE(errors.empty()) << errors.front();
}
