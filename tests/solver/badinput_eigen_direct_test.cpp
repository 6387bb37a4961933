// Bad-input hardening, Eigen direct solvers: LU and QR looped forever inside
// Eigen on an all-zero system; the input is checked first, reported once.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

// Eight free points, no mass, no force field: the system matrix is zero.
std::string no_mass(const std::string& linear_solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  )" + linear_solver + R"(
  <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0 3 0 0 0 1 0 1 1 0 2 1 0 3 1 0"/>
</Node>)";
}

class BadInputEigenDirect : public ::testing::Test {
 protected:
  TempDir dir;
};

}  // namespace

TEST_F(BadInputEigenDirect, EigenDirectSolversStopOnAZeroMatrix) {
  for (const char* s : {"EigenSparseLU", "EigenSparseQR", "EigenSimplicialLDLT", "EigenSimplicialLLT"}) {
    const Outcome o = run_xml(dir, no_mass(std::string("<") + s + " name=\"solver\"/>"), 5);  // was: endless loop
    EXPECT_TRUE(o.init_ok) << s << o.all();
    EXPECT_LE(o.steps, 1) << s << ": the run stops at the first step";
    EXPECT_TRUE(any_contains_all(o.errors, {"'solver'", "Solver cannot factorize", "the system matrix is zero"}))
        << s << o.all();
    int n = 0;
    for (const auto& e : o.errors) n += e.find("cannot factorize") != std::string::npos;
    EXPECT_EQ(n, 1) << s << ": reported once";
  }
}

TEST_F(BadInputEigenDirect, EigenDirectSolversNameZeroRows) {
  // Springs between coincident points at rest give no stiffness; the mass covers only some DoFs.
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <EigenSparseLU name="solver"/>
  <MechanicalObject name="dofs" position="0 0 0 0 0 0 1 0 0"/>
  <UniformMass name="m" totalMass="1" indices="2"/>
</Node>)", 5);
  EXPECT_TRUE(any_contains_all(o.errors, {"'solver'", "rows are zero", "first: row 0"})) << o.all();
}
