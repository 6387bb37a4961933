#include "constraint/solver/unbuilt_gauss_seidel_constraint_solver.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "constraint/solver/resolution.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void UnbuiltGaussSeidelConstraintSolver::build_system(const ConstraintParams& p) {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  sequence_.resize(n);
  std::iota(sequence_.begin(), sequence_.end(), 0);
  // Active corrections, in the solver's order; those without the unbuilt
  // interface cannot take part (one error).
  auto active = [](ConstraintCorrection* cc) {
    return cc->state() == ComponentState::valid && !cc->node()->sleeping.value() && cc->supports_unbuilt();
  };
  for (ConstraintCorrection* cc : scope_.corrections) {
    if (cc->state() == ComponentState::valid && !cc->supports_unbuilt() && !warned_unsupported_) {
      warned_unsupported_ = true;
      msg_error(cc->describe() + " has no unbuilt resolution: its body is ignored by this solver (use a built "
                "solver such as BlockGaussSeidelConstraintSolver)");
    }
    if (active(cc)) cc->reset_for_unbuilt(p, P.f, sequence_);
  }
  // For each block: the corrections that hold its first row, and their
  // compliance on the block's rows (W holds only these diagonal blocks).
  block_at_row_.assign(n, -1);
  owners_begin_.clear();
  owners_.clear();
  for (std::size_t b = 0; b < P.blocks.size(); ++b) {
    const ConstraintBlock& blk = P.blocks[b];
    block_at_row_[blk.first] = static_cast<int>(b);
    owners_begin_.push_back(static_cast<int>(owners_.size()));
    for (ConstraintCorrection* cc : scope_.corrections) {
      if (!active(cc) || !cc->has_constraint_row(blk.first)) continue;
      owners_.push_back(cc);
      cc->add_block_diagonal_compliance(P, blk.first, blk.first + blk.rows);
    }
    if (owners_.size() == static_cast<std::size_t>(owners_begin_.back()) && !warned_orphan_) {
      warned_orphan_ = true;
      msg_error("no constraint correction holds row " + std::to_string(blk.first) +
                ": its block has zero compliance (add a constraint correction to the constrained body)");
    }
  }
  owners_begin_.push_back(static_cast<int>(owners_.size()));
  const double reg = regularization_term.value();
  if (n > 0 && reg > std::numeric_limits<double>::epsilon())
    for (int i = 0; i < n; ++i) P.w(i, i) += reg;
}

void UnbuiltGaussSeidelConstraintSolver::solve_system() {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  if (n == 0) return;
  double* f = P.f.data();
  const double tol = effective_tolerance();
  for (ConstraintBlock& b : P.blocks) resolution_init(b, P, f);
  // SOFA erases the forces after init: the warm starts are not used.
  std::fill(P.f.begin(), P.f.end(), 0.0);
  df_.assign(n, 0.0);
  const double s = sor.value();
  int iter = 0;
  bool converged = false;
  double error = 0.0;
  const int max_it = std::max(0, max_iterations.value());
  for (iter = 0; iter < max_it; ++iter) {
    bool verified = true;
    if (s != 1.0) sor_copy_.assign(P.f.begin(), P.f.end());
    error = 0.0;
    for (std::size_t k = 0; k < sequence_.size();) {
      const int j = sequence_[k];
      const int bi = j >= 0 && j < n ? block_at_row_[j] : -1;
      if (bi < 0) {
        // Only a reordered sequence (wire optimisation) can point inside a block.
        if (!warned_sequence_) {
          warned_sequence_ = true;
          msg_error("the row order given by the constraint corrections visits row " + std::to_string(j) +
                    ", which does not start a block: it is skipped");
        }
        ++k;
        continue;
      }
      const ConstraintBlock& b = P.blocks[bi];
      const int nb = b.rows;
      f_old_.assign(f + j, f + j + nb);
      for (int l = 0; l < nb; ++l) P.d[j + l] = P.dfree[j + l];
      for (int o = owners_begin_[bi]; o < owners_begin_[bi + 1]; ++o)
        owners_[o]->add_constraint_displacement(P.d, j, j + nb);
      resolution_solve(b, P, P.d.data(), f);
      error += resolution_error(b, P, f, f_old_.data(), tol, verified);
      // The corrections learn the change of force (when the block pushes or pushed).
      bool update = false;
      for (int l = 0; l < nb; ++l) update = update || f[j + l] != 0.0 || f_old_[l] != 0.0;
      if (update) {
        for (int l = 0; l < nb; ++l) df_[j + l] = f[j + l] - f_old_[l];
        for (int o = owners_begin_[bi]; o < owners_begin_[bi + 1]; ++o) owners_[o]->set_constraint_dforce(df_, j, j + nb);
      }
      k += nb;
    }
    if (s != 1.0)
      for (int j = 0; j < n; ++j) f[j] = s * f[j] + (1 - s) * sor_copy_[j];
    if (all_verified.value() ? verified : error < tol) {
      converged = true;
      break;
    }
  }
  iterations_ = iter + 1;
  error_ = error;
  converged_ = converged;
  for (ConstraintBlock& b : P.blocks) resolution_store(b, f);
}

void register_unbuilt_gauss_seidel_constraint_solver(Registry& r) {
  ComponentInfo info;
  info.name = "UnbuiltGaussSeidelConstraintSolver";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "Gauss-Seidel on the diagonal blocks of W, coupling through the constraint corrections";
  info.create = creator<UnbuiltGaussSeidelConstraintSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
