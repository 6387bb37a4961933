// MechanicalOps: the operations ODE and linear solvers apply to the subtree
// of their node ("scope"), as plain loops over lists gathered once.
//
// Mirrors SOFA's mechanical operations (spec/framework.md §6): vector
// operations act on independent states only; forces are computed top-down
// and mapped up bottom-up (f_parent += Jᵀ f_child); projective constraints
// filter derivatives.
#pragma once

#include <cstdint>
#include <vector>

#include "core/roles.h"

namespace sinew {

class Node;

class MechanicalOps {
 public:
  explicit MechanicalOps(Node& node);
  // Re-gathers the scope.
  void rebuild();
  // Re-gathers the scope when the graph's structure version moved since the
  // last gathering (objects added or removed, a node deactivated, a component
  // made invalid). One comparison when nothing changed: call it at the start
  // of every operation sequence (each solve).
  void sync();

  Node& node() const { return *node_; }
  double context_dt() const;
  const std::vector<MechanicalState*>& independent_states() const { return independent_; }
  const std::vector<MechanicalState*>& all_states() const { return states_; }
  const std::vector<ForceField*>& force_fields() const { return force_fields_; }
  const std::vector<Mass*>& masses() const { return masses_; }
  const std::vector<Mapping*>& mappings() const { return mappings_; }
  // Every valid mapping of the scope, top-down: mechanical ones and those to visual models or pruned states.
  const std::vector<Mapping*>& all_mappings() const { return all_mappings_; }
  const std::vector<ProjectiveConstraint*>& projective_constraints() const { return constraints_; }

  // A fresh vector id of derivatives (zero on first use, kept afterwards).
  static int alloc_vec();
  // A fresh vector id of coordinates (positions: a rigid DoF has 7 scalars, the
  // identity rotation on first use).
  static int alloc_coord_vec();

  // ---- vector operations on independent states
  void v_clear(int r);                         // r = 0
  void v_eq(int r, int a);                     // r = a
  void v_peq(int r, int a, double f = 1.0);    // r += f·a
  void v_teq(int r, double f);                 // r *= f
  void v_op(int r, int a, int b, double f);    // r = a + f·b
  // p = r + β·p, written as SOFA does (p·β + r)
  void v_scale_add(int p, double beta, int r);
  double v_dot(int a, int b) const;            // sums x²+y²+z² per DOF, then over DOFs
  // v += fa·a ; x = x + fx·v (per DOF, using the updated v): the integration step.
  void v_integrate(int v, int a, double fa, int x_out, int x_in, double fx);
  std::size_t independent_dofs() const;
  // False when a vector of an independent state holds a NaN or an infinity.
  bool all_finite(int id) const;        // total scalar count of independent derivatives

  // ---- mechanics
  // f = external + Σ force fields, mapped forces accumulated bottom-up.
  // x, v: the positions and velocities the force fields read (RungeKutta stages use temporaries).
  void compute_force(int f, bool clear = true, bool accumulate = true, int x = kPosition, int v = kVelocity);
  // df (+)= m·M·dx + b·B·dx + k·K·dx, with per-component Rayleigh factors (§6.3).
  void add_mbk_dx(int df, double m, double b, double k, int dx = kDx, bool clear = true, bool accumulate = true);
  // Same with dx := velocity.
  void add_mbk_v(int df, double m, double b, double k, bool clear = true, bool accumulate = true);
  // res += factor · M · dx over masses.
  void add_mdx(int res, int dx, double factor);
  // a = M⁻¹ f
  void acc_from_f(int a, int f);
  void add_separate_gravity(double dt, int v);
  // Top-down J·dx through mechanical mappings; clears df on every state first.
  void propagate_dx_and_reset_df(int dx, int df);
  void propagate_dx(int dx);
  void propagate_x_and_v(int x, int v);
  void project_response(int dx);
  void project_position(int x, double t);
  void project_velocity(int v, double t);

  // Factors of the system matrix (set by the ODE solver, read by matrix-free products).
  double m_fact = 0, b_fact = 0, k_fact = 0;

 private:
  Node* node_;
  std::uint64_t built_version_ = 0;
  std::vector<MechanicalState*> states_, independent_, mapped_;
  std::vector<ForceField*> force_fields_;
  std::vector<Mass*> masses_;
  std::vector<Mapping*> mappings_;      // mechanical mappings, top-down order
  std::vector<Mapping*> all_mappings_;  // including mappings to visual models
  std::vector<ProjectiveConstraint*> constraints_;
};

}  // namespace sinew
