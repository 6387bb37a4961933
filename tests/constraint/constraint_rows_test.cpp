// Constraint Jacobian rows: storage (sorted, duplicates summed) and their
// mapping through every kind of mapping, checked as the transpose of the
// mapping's velocity Jacobian: r·(J·dv) = (Jᵀ·r)·dv for random rows and dv.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "core/constraint_matrix.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(ConstraintMatrix, CompressSortsByRowThenDofAndSumsDuplicates) {
  ConstraintMatrix m;
  m.clear(3);
  const double a[3] = {1, 2, 3}, b[3] = {10, 20, 30}, c[3] = {-1, 0, 1};
  m.add(4, 2, a);
  m.add(1, 7, b);
  m.add(4, 2, c);  // same (row, dof): summed
  m.add(4, 0, b);
  m.add_component(1, 7, 2, 0.5);
  m.compress();
  ASSERT_EQ(m.rows().size(), 2u);
  EXPECT_EQ(m.rows()[0].id, 1);
  EXPECT_EQ(m.rows()[1].id, 4);
  ASSERT_EQ(m.entries().size(), 3u);
  EXPECT_EQ(m.entries()[0].dof, 7);
  EXPECT_DOUBLE_EQ(m.value(0)[2], 30.5);
  EXPECT_EQ(m.entries()[1].dof, 0);  // row 4: DoF 0 before DoF 2
  EXPECT_EQ(m.entries()[2].dof, 2);
  EXPECT_DOUBLE_EQ(m.value(2)[0], 0.0);
  EXPECT_DOUBLE_EQ(m.value(2)[1], 2.0);
  EXPECT_DOUBLE_EQ(m.value(2)[2], 4.0);
  m.zero_dof(2, 1, 2);
  EXPECT_DOUBLE_EQ(m.value(2)[1], 0.0);
  EXPECT_DOUBLE_EQ(m.value(2)[2], 0.0);
}

// A parent state (template `in`) mapped to a child Vec3d state by `mapping`.
struct MappingCase {
  const char* name;
  const char* parent;  // MechanicalObject attributes of the parent
  const char* extra;   // components of the parent node before the child (topologies)
  const char* child;   // child node content: MechanicalObject + mapping
};

class MappedRows : public ::testing::TestWithParam<MappingCase> {};

TEST_P(MappedRows, AreTheTransposeOfTheVelocityJacobian) {
  const MappingCase& c = GetParam();
  const std::string xml = std::string(R"(<Node name="root" dt="0.01"><Node name="parent"><MechanicalObject name="in" )") +
                          c.parent + "/>" + c.extra + R"(<Node name="child">)" + c.child + "</Node></Node></Node>";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  Node* parent = s.root->find_child_named("parent");
  MechanicalState* in = parent->mechanical_state;
  Node* child = parent->find_child_named("child");
  MechanicalState* out = child->mechanical_state;
  Mapping* map = child->mechanical_mapping;
  ASSERT_TRUE(in && out && map);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  // Random velocities of the parent, mapped to the child.
  std::vector<double>& v = in->write(kVelocity);
  for (double& x : v) x = u(rng);
  map->apply_j(kVelocity, kVelocity);
  const std::vector<double>& vc = out->read(kVelocity);
  // Three random rows on the child, one of them touching every child point twice.
  in->constraint_jacobian().clear(in->info().deriv_width);
  ConstraintMatrix& rows = out->constraint_jacobian();
  rows.clear(3);
  std::vector<std::vector<double>> dense(3, std::vector<double>(3 * out->size(), 0.0));
  for (int r = 0; r < 3; ++r)
    for (std::size_t p = 0; p < out->size(); ++p) {
      if (r < 2 && u(rng) < 0) continue;
      for (int twice = 0; twice < (r == 2 ? 2 : 1); ++twice) {
        const double val[3] = {u(rng), u(rng), u(rng)};
        rows.add(r, static_cast<int>(p), val);
        for (int k = 0; k < 3; ++k) dense[r][3 * p + k] += val[k];
      }
    }
  ASSERT_TRUE(map->apply_jt_constraints());
  ConstraintMatrix& mapped = in->constraint_jacobian();
  mapped.compress();
  const int w = in->info().deriv_width;
  for (int r = 0; r < 3; ++r) {
    double lhs = 0;
    for (std::size_t k = 0; k < vc.size(); ++k) lhs += dense[r][k] * vc[k];
    double rhs = 0;
    for (const ConstraintMatrix::Row& row : mapped.rows()) {
      if (row.id != r) continue;
      for (int e = row.begin; e < row.end; ++e)
        for (int k = 0; k < w; ++k) rhs += mapped.value(e)[k] * v[mapped.entries()[e].dof * w + k];
    }
    EXPECT_NEAR(lhs, rhs, 1e-12 * (1 + std::abs(lhs))) << c.name << " row " << r;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Mappings, MappedRows,
    ::testing::Values(
        MappingCase{"identity", R"(position="0 0 0  1 2 3  -1 0.5 2")", "",
                    R"(<MechanicalObject/><IdentityMapping/>)"},
        MappingCase{"rigid", R"(template="Rigid3" position="1 2 3  0.1 0.2 0.3 0.927362  -1 0 0  0 0 0 1")", "",
                    R"(<MechanicalObject position="1 0 0  0 1 0  0 0 1  1 1 1"/><RigidMapping rigidIndexPerPoint="0 0 1 1"/>)"},
        MappingCase{"subset", R"(position="0 0 0  1 2 3  -1 0.5 2  4 4 4")", "",
                    R"(<MechanicalObject/><SubsetMapping indices="3 1 1"/>)"},
        MappingCase{"tubular", R"(template="Rigid3" position="1 2 3  0.1 0.2 0.3 0.927362  -1 0 0  0 0 0 1")", "",
                    R"(<MechanicalObject/><TubularMapping nbPointsOnEachCircle="5" radius="0.3"/>)"},
        MappingCase{"barycentric", R"(position="0 0 0  1 0 0  0 1 0  0 0 1")",
                    R"(<MeshTopology tetrahedra="0 1 2 3"/>)",
                    R"(<MechanicalObject position="0.1 0.2 0.3  0.25 0.25 0.25  0.6 0.1 0.1"/><BarycentricMapping/>)"}),
    [](const ::testing::TestParamInfo<MappingCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace sinew
