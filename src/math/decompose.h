// Matrix decompositions that must reproduce SOFA's numbers to round-off
// (helper::Decompose in SOFA). Arithmetic is written out by hand in SOFA's
// evaluation order; Eigen is used only as storage.
#pragma once

#include <Eigen/Geometry>  // math/types.h names Eigen::Quaterniond but only includes Eigen/Core

#include "math/types.h"

namespace sinew {

// Orthogonal factor Q of the polar decomposition M = Q·S (S symmetric
// positive semi-definite), by Higham's scaled Newton iteration on Mᵀ, stopped
// when ‖Mk − Mk₊₁‖₁ ≤ 1e-8·‖Mk₊₁‖₁ (spec mechanics.md §2.0).
// det(Q) = sign(det M): for an orientation-reversing M the result is a
// reflection, not a rotation. If an iterate becomes singular (exact zero
// determinant) the iteration stops and returns the current iterate, as SOFA
// does; *singular (when given) tells the caller.
Mat3 polar_rotation(const Mat3& M, bool* singular = nullptr);

// Rotation factor of M by singular value decomposition (SOFA's
// polarDecomposition_stable): R = U·Vᵀ with the singular vectors of the
// smallest singular value flipped when needed so that det R = +1, even for a
// reflecting or singular M. SOFA's own SVD routine is not reproduced: R agrees
// with SOFA's to round-off, not bit for bit.
Mat3 stable_polar_rotation(const Mat3& M);

// Both factors: Q as above and S = Qᵀ·M (the last iterate times M, as SOFA
// computes it), then set to ½(S + Sᵀ) so that it is exactly symmetric.
void polar_decomposition(const Mat3& M, Mat3& Q, Mat3& S, bool* singular = nullptr);

// Matrix 1-norm (largest column sum of absolute values) and ∞-norm (largest
// row sum), summed in SOFA's order (row 0, then 1, then 2 / column 0, 1, 2).
double one_norm(const Mat3& A);
double inf_norm(const Mat3& A);

}  // namespace sinew
