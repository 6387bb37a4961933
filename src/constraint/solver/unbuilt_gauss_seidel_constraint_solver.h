// UnbuiltGaussSeidelConstraintSolver (spec/interaction.md §5.4.3): Gauss-Seidel
// without the assembled W. Only the diagonal blocks of W are built (each
// correction's block-diagonal compliance); the coupling between blocks comes
// from the corrections, which keep the constraint force accumulated on their
// DoFs and the displacement it causes (add_constraint_displacement /
// set_constraint_dforce).
//
// Kept from SOFA: the warm starts written by the blocks' init are discarded
// (forces start at zero), and UncoupledConstraintCorrection's block
// compliance lacks the integration factor its correction applies.
#pragma once

#include <vector>

#include "constraint/solver/generic_constraint_solver.h"

namespace sinew {

class UnbuiltGaussSeidelConstraintSolver : public GenericConstraintSolver {
 protected:
  void build_system(const ConstraintParams& p) override;
  void solve_system() override;

 private:
  std::vector<int> sequence_;                  // rows in solving order (a correction may reorder them)
  std::vector<int> block_at_row_;              // index of the block starting at each row, -1 elsewhere
  std::vector<int> owners_begin_;              // per block: its corrections are owners_[begin[b], begin[b+1])
  std::vector<ConstraintCorrection*> owners_;  // corrections whose state has the block's first row
  std::vector<double> f_old_, df_, sor_copy_;
  bool warned_unsupported_ = false, warned_orphan_ = false, warned_sequence_ = false;
};

}  // namespace sinew
