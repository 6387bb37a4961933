// PreconditionedMatrixFreeSystem: the matrix-free (GraphScattered) system of
// PCGLinearSolver (spec/solvers.md §2.3, §2.6).
//
// build_system only memorises the factors of A = m·M + b·B + k·K, then every
// `assemblingRate` builds (the first one included) asks the preconditioner's
// linear system to assemble with the same factors. product(p, q) is the
// matrix-free q = A·p over the solver's scope, projected.
#pragma once

#include "core/mechanical_ops.h"
#include "core/roles.h"
#include "solver/system/matrix_linear_system.h"

namespace sinew {

class PreconditionedMatrixFreeSystem final : public Component {
 public:
  PreconditionedMatrixFreeSystem() { assembling_rate.add_alias("update_step"); }

  Field<VecNi<2>> matrix_size{this, "matrixSize", VecNi<2>(0, 0), "size of the assembled matrix (output)",
                              "LinearSystem"};
  Field<bool> enable_assembly{this, "enableAssembly", true, "assemble the matrix", "LinearSystem"};
  Field<unsigned> assembling_rate{this, "assemblingRate", 1u,
                                  "refresh the preconditioner every N time steps / Newton iterations", "LinearSystem"};
  Link<MatrixLinearSystem> preconditioner_system{this, "preconditionerSystem",
                                                 "linear system assembling the preconditioner"};

  void init() override { reinit_counter(); }
  void reset() override { reinit_counter(); }

  // Memorises the factors; assembles the preconditioner's system every assemblingRate calls.
  void build_system_matrix(MechanicalOps& ops, double m, double b, double k);
  // q = A·p (matrix-free, projected); p and q are vector ids of the scope.
  void product(MechanicalOps& ops, int p, int q) const;

  double m_fact() const { return m_; }
  double b_fact() const { return b_; }
  double k_fact() const { return k_; }
  // Number of preconditioner assemblies triggered so far (tests).
  long preconditioner_builds() const { return builds_; }

  // The PCG that uses this system (automatic linking takes unused systems only).
  Component* user = nullptr;

 private:
  void reinit_counter() { counter_ = assembling_rate.value(); }
  double m_ = 0, b_ = 0, k_ = 0;
  unsigned counter_ = 1;
  long builds_ = 0;
};

}  // namespace sinew
