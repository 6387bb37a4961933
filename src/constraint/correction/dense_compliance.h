// Products of a dense per-state compliance C (PrecomputedConstraintCorrection,
// spec/interaction.md §5.3) with the rows of the state's constraint Jacobian.
//
// C is n×n row-major, n = DoFs × w (w: derivative width, Vec3d 3, Rigid3d 6);
// block (a, b) is the w×w response of DoF a to a unit force on DoF b. Sums
// run in SOFA's order (a row's entries in DoF order, components in order) so
// W agrees with SOFA's to the last bit.
#pragma once

#include <cstddef>
#include <vector>

#include "core/constraint_matrix.h"

namespace sinew::dense_compliance {

// Scratch kept by the caller between steps (no allocation once warm).
struct Work {
  std::vector<int> slot;     // per DoF: index among the active DoFs, or −1
  std::vector<int> active;   // DoFs touched by J, ascending
  std::vector<double> v;     // per (active DoF, row): C(dof, ·)·J_rowᵀ, w values
};

// Marks the DoFs J touches (work.active ascending) and computes work.v.
// Needs a compressed J whose DoFs are < dofs.
void prepare(const ConstraintMatrix& J, const double* C, std::size_t dofs, int w, Work& work);

// W(i, j) += factor·J_i·C·J_jᵀ over the rows of J (after prepare), W being
// `ld` wide and indexed by row id (by_id) or by the row's position in J.
// `reg` goes on the diagonal once per entry of the row, as SOFA adds it.
void add_jcjt(const ConstraintMatrix& J, const Work& work, int w, double factor, double reg, double* W, int ld,
              bool by_id);

// out = Jᵀλ on the state (n values, cleared first), rows in order; rows whose
// λ is zero are skipped when `skip_zero` (SOFA's LCP path), their DoFs then
// not marked. `active` receives the DoFs touched, ascending.
void jt_lambda(const ConstraintMatrix& J, const std::vector<double>& lambda, int w, bool skip_zero,
               std::vector<double>& out, std::vector<int>& active, std::vector<int>& mark);

// dx = Σ_{f in active, ascending} C(·, f)·force_f over every DoF (dx cleared first).
void apply(const double* C, std::size_t dofs, int w, const std::vector<int>& active, const std::vector<double>& force,
           std::vector<double>& dx);

}  // namespace sinew::dense_compliance
