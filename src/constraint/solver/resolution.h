// The projection laws of constraint blocks (SOFA's ConstraintResolution
// classes, spec/interaction.md §5.4.1), as free functions over a block and
// the problem's arrays.
//
// init: prepares the block from W (inverse of a 3×3 block, cached W entries)
// and writes its warm start into f; resolve: updates f[first..] from the
// current violation d; store: keeps the forces for the next step's warm start.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "core/constraint_problem.h"

namespace sinew {

// The diagonal block of a bilateral_n block and its LDLᵀ (SOFA's
// BilateralConstraintResolutionNDof). Owned by the constraint so that its
// storage is reused from step to step.
struct BlockFactor {
  Eigen::MatrixXd w;
  Eigen::LDLT<Eigen::MatrixXd> ldlt;
  Eigen::VectorXd step;  // scratch of the solve
};

// Prepares the block; false when a 3×3 bilateral block of W is singular
// (the block then keeps zero forces).
bool resolution_init(ConstraintBlock& b, const ConstraintProblem& p, double* f);
// One projection of the block; d holds the violation with the current forces
// (the friction law updates its tangential entries in place, as SOFA does).
void resolution_solve(const ConstraintBlock& b, const ConstraintProblem& p, double* d, double* f);
void resolution_store(ConstraintBlock& b, const double* f);
// Error of one block after a projection (SOFA's Gauss-Seidel measure): |W_jj·Δf| for
// one row, Σ_l ‖W_l,block·Δf‖ for more, rescaled by the block's own tolerance;
// clears `verified` when a line exceeds tol. f_old: the block's forces before.
double resolution_error(const ConstraintBlock& b, const ConstraintProblem& p, const double* f, const double* f_old,
                        double tol, bool& verified);

}  // namespace sinew
