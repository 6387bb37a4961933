#include "constraint/solver/resolution.h"

#include <cmath>

#include "math/sofa_vec.h"

namespace sinew {

bool resolution_init(ConstraintBlock& b, const ConstraintProblem& p, double* f) {
  const int j = b.first;
  if (b.disabled) {
    for (int r = 0; r < b.rows; ++r) f[j + r] = 0.0;
    return false;
  }
  switch (b.kind) {
    case ConstraintBlock::Kind::bilateral:
      if (b.warm) f[j] = b.warm[0];
      return true;
    case ConstraintBlock::Kind::bilateral3: {
      // SOFA's determinant, zero test and cofactor order (type::invertMatrix), so that
      // warm-started blocks match.
      Mat3 m, inv;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = p.w(j + r, j + c);
      const double det = sofa_det(m);
      const bool ok = std::isfinite(det) && sofa_invert(m, det, inv);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) b.inv[r * 3 + c] = ok ? inv(r, c) : 0.0;
      if (b.warm)
        for (int r = 0; r < 3; ++r) f[j + r] = b.warm[r];
      return ok;
    }
    case ConstraintBlock::Kind::unilateral:
      return true;
    case ConstraintBlock::Kind::unilateral_friction:
      b.w[0] = p.w(j, j);
      b.w[1] = p.w(j, j + 1);
      b.w[2] = p.w(j, j + 2);
      b.w[3] = p.w(j + 1, j + 1);
      b.w[4] = p.w(j + 1, j + 2);
      b.w[5] = p.w(j + 2, j + 2);
      return true;
    case ConstraintBlock::Kind::bilateral_n: {
      BlockFactor& F = *b.factor;
      F.w.resize(b.rows, b.rows);
      for (int r = 0; r < b.rows; ++r)
        for (int c = 0; c < b.rows; ++c) F.w(r, c) = p.w(j + r, j + c);
      F.ldlt.compute(F.w);
      F.step.resize(b.rows);
      return F.ldlt.info() == Eigen::Success;
    }
    case ConstraintBlock::Kind::stopper:
      b.w[0] = p.w(j, j);
      b.w[1] = 1.0 / b.w[0];
      f[j] = 0.0;
      return true;
    case ConstraintBlock::Kind::augmented_friction:
      return true;  // no warm start (SOFA's previous-force container is never given)
  }
  return true;
}

void resolution_solve(const ConstraintBlock& b, const ConstraintProblem& p, double* d, double* f) {
  if (b.disabled) return;
  const int j = b.first;
  switch (b.kind) {
    case ConstraintBlock::Kind::bilateral:
      f[j] -= d[j] / p.w(j, j);
      return;
    case ConstraintBlock::Kind::bilateral3:
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) f[j + r] -= d[j + c] * b.inv[r * 3 + c] * b.load;
      return;
    case ConstraintBlock::Kind::unilateral:
      f[j] -= d[j] / p.w(j, j);
      if (f[j] < 0) f[j] = 0.0;
      return;
    case ConstraintBlock::Kind::unilateral_friction: {
      const double fn0 = f[j];
      f[j] -= d[j] / b.w[0];
      if (f[j] < 0) {
        f[j] = f[j + 1] = f[j + 2] = 0.0;
        return;
      }
      d[j + 1] += b.w[1] * (f[j] - fn0);
      d[j + 2] += b.w[2] * (f[j] - fn0);
      // One averaged tangential compliance for both directions (SOFA).
      f[j + 1] -= 2 * d[j + 1] / (b.w[3] + b.w[5]);
      f[j + 2] -= 2 * d[j + 2] / (b.w[3] + b.w[5]);
      const double norm_t = std::sqrt(f[j + 1] * f[j + 1] + f[j + 2] * f[j + 2]);
      const double fn = b.mu * f[j];
      if (norm_t > fn) {
        const double factor = fn / norm_t;
        f[j + 1] *= factor;
        f[j + 2] *= factor;
      }
      return;
    }
    case ConstraintBlock::Kind::bilateral_n: {
      BlockFactor& F = *b.factor;
      F.step = F.ldlt.solve(Eigen::Map<const Eigen::VectorXd>(d + j, b.rows));
      for (int r = 0; r < b.rows; ++r) f[j + r] -= F.step[r];
      return;
    }
    case ConstraintBlock::Kind::augmented_friction: {
      // SOFA's AugmentedLagrangianResolutionWithFriction: steps of −ε·d; outside
      // the cone the tangential step is along the slip, scaled by μ·ε·d_n.
      const double eps = b.epsilon;
      f[j] -= d[j] * eps;
      if (f[j] < 0) {
        f[j] = f[j + 1] = f[j + 2] = 0.0;
        return;
      }
      const double ft0 = f[j + 1] - d[j + 1] * eps;
      const double ft1 = f[j + 2] - d[j + 2] * eps;
      const double criteria = std::sqrt(std::pow(ft0, 2.0) + std::pow(ft1, 2.0)) - b.mu * std::fabs(f[j]);
      if (criteria < 0) {
        f[j + 1] = ft0;
        f[j + 2] = ft1;
      } else {
        const double norm_s = std::sqrt(std::pow(d[j + 1], 2.0) + std::pow(d[j + 2], 2.0));
        f[j + 1] -= b.mu * d[j] * eps * d[j + 1] / norm_s;
        f[j + 2] -= b.mu * d[j] * eps * d[j + 2] / norm_s;
      }
      return;
    }
    case ConstraintBlock::Kind::stopper: {
      // The value the row would have without its own force, pushed back onto the bounds.
      const double free = d[j] - b.w[0] * f[j];
      if (free > b.hi)
        f[j] = (b.hi - free) * b.w[1];
      else if (free < b.lo)
        f[j] = (b.lo - free) * b.w[1];
      else
        f[j] = 0;
      return;
    }
  }
}

double resolution_error(const ConstraintBlock& b, const ConstraintProblem& p, const double* f, const double* f_old,
                        double tol, bool& verified) {
  const int j = b.first, nb = b.rows;
  double block_error = 0.0;
  if (nb > 1) {
    for (int l = 0; l < nb; ++l) {
      double line = 0.0;
      for (int m = 0; m < nb; ++m) {
        const double e = p.w(j + l, j + m) * (f[j + m] - f_old[m]);
        line += e * e;
      }
      line = std::sqrt(line);
      if (line > tol) verified = false;
      block_error += line;
    }
  } else {
    block_error = std::fabs(p.w(j, j) * (f[j] - f_old[0]));
    if (block_error > tol) verified = false;
  }
  if (b.tolerance != 0.0) {
    if (block_error > b.tolerance) verified = false;
    block_error *= tol / b.tolerance;
  }
  return block_error;
}

void resolution_store(ConstraintBlock& b, const double* f) {
  if (b.disabled) return;
  if (b.warm)
    for (int r = 0; r < b.rows; ++r) b.warm[r] = f[b.first + r];
  if (b.active) *b.active = f[b.first] != 0.0;
  if (b.notify) b.notify->store_lambda(b.first, f + b.first, b.rows);
}

}  // namespace sinew
