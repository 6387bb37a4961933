// ParallelHexahedronFEMForceField: HexahedronFEMForceField on the task scheduler. Forces,
// force derivatives and a 10-step trajectory must be bit-identical to the sequential
// component on a grid above the kernel's parallel threshold, whatever nbThreads says.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/mechanical_ops.h"
#include "forcefield/fem/hexa_fem.h"
#include "forcefield/fem/hexahedron_fem_force_field.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

// 9·9·29 = 2349 hexahedra, clamped at z = 0.
std::string bar(const char* ff, const char* extra) {
  char buf[2048];
  std::snprintf(buf, sizeof buf,
                "<Node dt=\"0.01\" gravity=\"0 -9.81 0\"><DefaultAnimationLoop/>"
                "<EulerImplicitSolver rayleighStiffness=\"0.1\" rayleighMass=\"0.1\"/>"
                "<CGLinearSolver iterations=\"25\" tolerance=\"1e-9\" threshold=\"1e-9\"/>"
                "<MechanicalObject name=\"dofs\"/><UniformMass vertexMass=\"1\"/>"
                "<RegularGridTopology nx=\"10\" ny=\"10\" nz=\"30\" xmin=\"-1.5\" xmax=\"1.5\" ymin=\"-1.5\" "
                "ymax=\"1.5\" zmin=\"0\" zmax=\"19\"/>"
                "<BoxROI name=\"box\" box=\"-1.5 -1.5 0 1.5 1.5 0.0001\"/>"
                "<FixedProjectiveConstraint indices=\"@box.indices\"/>"
                "<%s name=\"fem\" youngModulus=\"400000\" poissonRatio=\"0.4\"%s/></Node>",
                ff, extra);
  return buf;
}

struct Eval {
  std::vector<double> f, df, x10;
};

Eval evaluate(const char* ff, const char* extra) {
  Eval r;
  auto s = test::load(bar(ff, extra));
  auto* fem = test::get<HexahedronFEMForceField>(*s.root, "fem");
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  EXPECT_NE(fem, nullptr);
  EXPECT_NE(mo, nullptr);
  if (!fem || !mo) return r;
  EXPECT_GE(fem->kernel().size(), fem::HexaFEM::kParallelMinElements);
  // A random deformation and a random dx, the same for both components.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  const int dx = MechanicalOps::alloc_vec(), df = MechanicalOps::alloc_vec();
  std::vector<double> x0 = mo->read(kPosition);
  auto& x = mo->write(kPosition);
  for (auto& v : x) v += u(rng);
  auto& d = mo->write(dx);
  d.assign(x.size(), 0.0);
  for (auto& v : d) v = u(rng);
  auto& f = mo->write(kForce);
  f.assign(x.size(), 0.0);
  MechParams p;
  fem->add_force(p);
  r.f = mo->read(kForce);
  MechParams q;
  q.dx = dx;
  q.df = df;
  mo->write(df).assign(x.size(), 0.0);
  fem->add_dforce(q, 0.7);
  r.df = mo->read(df);
  // Back to rest, then ten steps of the bar bending under gravity.
  mo->write(kPosition) = x0;
  for (int i = 0; i < 10; ++i) animate(*s.root);
  r.x10 = mo->read(kPosition);
  return r;
}

void expect_identical(const Eval& a, const Eval& b) {
  ASSERT_EQ(a.f.size(), b.f.size());
  ASSERT_EQ(a.x10.size(), b.x10.size());
  for (std::size_t i = 0; i < a.f.size(); ++i) {
    ASSERT_EQ(a.f[i], b.f[i]) << "force entry " << i;
    ASSERT_EQ(a.df[i], b.df[i]) << "dforce entry " << i;
  }
  for (std::size_t i = 0; i < a.x10.size(); ++i) ASSERT_EQ(a.x10[i], b.x10[i]) << "position entry " << i;
}

TEST(ParallelHexahedronFEMForceField, BitIdenticalToHexahedronFEMForceField) {
  const Eval seq = evaluate("HexahedronFEMForceField", " method=\"large\"");
  const Eval par = evaluate("ParallelHexahedronFEMForceField", " method=\"large\"");
  expect_identical(seq, par);
  // The bar did move: the comparison is not between two rest states.
  double moved = 0;
  for (double v : seq.f) moved = std::max(moved, std::abs(v));
  EXPECT_GT(moved, 1.0);
  const Eval one = evaluate("ParallelHexahedronFEMForceField", " method=\"large\" nbThreads=\"1\"");
  expect_identical(seq, one);
}

TEST(ParallelHexahedronFEMForceField, OtherMethodsWarnAndMatch) {
  const Eval seq = evaluate("HexahedronFEMForceField", " method=\"polar\"");
  const Eval par = evaluate("ParallelHexahedronFEMForceField", " method=\"polar\"");
  expect_identical(seq, par);
  auto s = test::load(bar("ParallelHexahedronFEMForceField", " method=\"small\""));
  animate(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning),
                                 "other methods than 'large'"));
}

TEST(ParallelHexahedronFEMForceField, NbThreadsResolvesAsSofa) {
  auto s = test::load(bar("ParallelHexahedronFEMForceField", " nbThreads=\"0\""));
  auto* fem = test::get<HexahedronFEMForceField>(*s.root, "fem");
  ASSERT_NE(fem, nullptr);
  const auto* field = fem->find_field("nbThreads");
  ASSERT_NE(field, nullptr);
  EXPECT_GE(std::stoi(field->text()), 1);  // 0 → every core
}

}  // namespace
}  // namespace sinew
