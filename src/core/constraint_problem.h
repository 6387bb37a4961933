// The Lagrangian constraint problem of one step (spec/interaction.md §5.2):
// W λ + dfree = d, with each block of rows projected by its resolution law.
//
// Plain data shared by the constraint components (which fill dfree and
// declare their blocks), the constraint corrections (which add their
// compliance to W) and the solvers (which find λ). Storage is reused from
// step to step.
#pragma once

#include <cstdint>
#include <vector>

#include "core/roles.h"

namespace sinew {

// Which quantity the constraints are solved for (SOFA's ConstraintOrder).
enum class ConstraintOrder : std::uint8_t { pos, vel, acc, pos_and_vel };

// The vectors a constraint step reads: free positions and velocities.
struct ConstraintParams {
  int x = kFreePosition;
  int v = kFreeVelocity;
  ConstraintOrder order = ConstraintOrder::pos_and_vel;
  double dt = 0;
};

// Factorisation of a bilateral_n block (constraint/solver/resolution.h),
// owned by the constraint that declares the block.
struct BlockFactor;
class LagrangianConstraint;

// A block of rows solved together (SOFA's ConstraintResolution), as data: the
// solver switches on `kind` (no virtual call per block and iteration).
struct ConstraintBlock {
  enum class Kind : std::uint8_t {
    bilateral,            // 1 row: f -= d / W_jj (warm start from *warm)
    bilateral3,           // 3 rows: f -= load · W_b⁻¹ d (warm start from warm[0..2])
    unilateral,           // 1 row: f -= d / W_jj, f = max(f, 0)
    unilateral_friction,  // 3 rows (n, t, s): Coulomb cone with coefficient mu
    bilateral_n,          // `rows` rows: f -= W_b⁻¹ d through an LDLᵀ of W_b kept in *factor
    stopper,              // 1 row: the free value d − W_jj f kept within [lo, hi]; f starts at 0
    augmented_friction,   // 3 rows (n, t, s): augmented Lagrangian steps −ε·d in the Coulomb cone
  };
  Kind kind = Kind::bilateral;
  int first = 0;   // first row
  int rows = 1;    // number of rows
  double mu = 0;   // unilateral_friction, augmented_friction
  double epsilon = 0;  // augmented_friction: penalty factor of the steps [force/length]
  double load = 1; // bilateral3
  double tolerance = 0;      // own tolerance (0: the solver's)
  double* warm = nullptr;    // previous forces: read at init, written at store (null: none)
  bool* active = nullptr;    // unilateral_friction: whether the contact pushed (written at store)
  // Set by the solver when a diagonal entry of the block in W is not positive
  // (no body can move along those rows): the block keeps zero forces.
  bool disabled = false;
  BlockFactor* factor = nullptr;  // bilateral_n (required)
  double lo = 0, hi = 0;     // stopper: bounds of the free value
  // Told the block's final forces at store (SOFA's storeLambda; null: nobody).
  LagrangianConstraint* notify = nullptr;
  // Filled by the solver at init.
  double inv[9] = {};        // bilateral3: W_b⁻¹ (row-major)
  double w[6] = {};          // unilateral_friction: W00 W01 W02 W11 W12 W22
};

struct ConstraintProblem {
  int n = 0;
  std::vector<double> W;      // n×n, row-major
  std::vector<double> dfree;  // violation at the free motion
  std::vector<double> f;      // λ
  std::vector<double> d;      // work: current violation
  std::vector<ConstraintBlock> blocks;  // in row order, covering rows 0..n-1

  void clear(int rows) {
    n = rows;
    W.assign(static_cast<std::size_t>(rows) * rows, 0.0);
    dfree.assign(rows, 0.0);
    f.assign(rows, 0.0);
    d.assign(rows, 0.0);
    blocks.clear();
  }
  double& w(int i, int j) { return W[static_cast<std::size_t>(i) * n + j]; }
  double w(int i, int j) const { return W[static_cast<std::size_t>(i) * n + j]; }
};

// ---------------------------------------------------------------- roles

// A Lagrangian constraint (SOFA's BaseLagrangianConstraint): rows of J on one
// or two states, their violation and how each block of rows is solved. The
// three calls come in this order, with the same numbering, every step.
class LagrangianConstraint : public Component {
 public:
  // Data every SOFA constraint set has: the solver group (unused by the
  // generic solvers), the first row of the last build (output) and the time
  // after which it stops (recorded; SOFA's Lagrangian path never reads it).
  Field<int> group{this, "group", 0, "ID of the group of constraints a solver handles", "Constraint"};
  Field<unsigned> constraint_index{this, "constraintIndex", 0u, "first row of this constraint (output)", "Constraint"};
  Field<double> end_time{this, "endTime", -1.0, "time after which the constraint stops (negative: never)",
                         "Constraint", "time"};

  // Appends its rows to its states' Jacobians (constraint_jacobian()),
  // numbered from `row`, which it advances.
  virtual void build_constraint_matrix(const ConstraintParams& p, int& row) = 0;
  // Writes the violation of its rows into dfree (indexed by row id).
  virtual void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) = 0;
  // Appends one block per group of its rows, in row order.
  virtual void constraint_resolutions(const ConstraintParams& p, std::vector<ConstraintBlock>& out) = 0;

  // What the LCP solver's warm start needs (SOFA's getConstraintInfo): groups
  // of rows with persistent ids. Called after build_constraint_matrix, only
  // by solvers with an initial guess. Default: no information (no warm start).
  struct BlockInfo {
    const LagrangianConstraint* parent = nullptr;
    int first_row = 0;   // row of the first group
    int lines = 1;       // rows per group
    int groups = 0;      // number of groups
    bool has_id = false; // whether ids[offset .. offset+groups) are persistent ids
    int offset = 0;      // index of the first group's id in the id vector
  };
  virtual void constraint_info(std::vector<BlockInfo>& blocks, std::vector<std::int64_t>& ids) {
    (void)blocks;
    (void)ids;
  }
  // The final forces of a block whose `notify` is this constraint (rows
  // first..first+rows-1), once per solve.
  virtual void store_lambda(int first, const double* f, int rows) {}
};

// A constraint correction (SOFA's BaseConstraintCorrection): the compliance
// of one independent state in constraint space, and the motion correction
// the constraint forces cause.
class ConstraintCorrection : public Component {
 public:
  Link<MechanicalState> mstate{this, "mstate", "state this correction acts on (default: the node's)"};
  void init() override;

  // W += compliance of the rows of this state's Jacobian (§5.3).
  virtual void add_compliance(const ConstraintParams& p, ConstraintProblem& problem) = 0;
  // dx = C·Jᵀλ; then (POS_AND_VEL) x = xf + xfactor·dx, v = vf + vfactor·dx,
  // (POS) x only, (VEL) v only. `dx_out` receives the applied correction.
  virtual void apply_correction(const ConstraintParams& p, const std::vector<double>& lambda, int x_out, int v_out,
                                int dx_out) = 0;

  // Unbuilt solvers and the LCP solver (§5.3 "unbuilt helpers"). Rows are
  // row ids of the problem; ranges are half-open [begin, end).
  // Whether this state's Jacobian has row `row` (SOFA's hasConstraintNumber).
  virtual bool has_constraint_row(int row) const;
  // Whether this correction supports the unbuilt interface below.
  virtual bool supports_unbuilt() const { return false; }
  // Starts an unbuilt resolution: cforce = Jᵀf of the initial forces; the
  // displacements cdisp start at zero (even when f is not: SOFA's way).
  // `sequence` (the rows in solving order) may be reordered (wire optimisation).
  virtual void reset_for_unbuilt(const ConstraintParams& p, const std::vector<double>& f, std::vector<int>& sequence) {
    (void)p;
    (void)f;
    (void)sequence;
  }
  // W[begin..end)² += compliance between those rows of this state (Uncoupled:
  // without the integration factor, SOFA's unbuilt quirk).
  virtual void add_block_diagonal_compliance(ConstraintProblem& problem, int begin, int end) {
    (void)problem;
    (void)begin;
    (void)end;
  }
  // d[i] += J_i·cdisp for rows i in [begin, end).
  virtual void add_constraint_displacement(std::vector<double>& d, int begin, int end) {
    (void)d;
    (void)begin;
    (void)end;
  }
  // cforce += Σ J_i·df_i for rows in [begin, end); cdisp follows on the touched DOFs.
  virtual void set_constraint_dforce(const std::vector<double>& df, int begin, int end) {
    (void)df;
    (void)begin;
    (void)end;
  }
  // LCP path: before the build (Uncoupled: externalForce = 0) ...
  virtual void reset_contact_force() {}
  // ... and after the solve: the correction of the forces f, written into
  // the state's position, velocity and dx from the free vectors.
  virtual void apply_contact_force(const ConstraintParams& p, const std::vector<double>& f) {
    (void)p;
    (void)f;
  }
};

// A constraint solver (SOFA's ConstraintSolver): builds the problem of the
// step, solves it and applies the corrections (§5.2).
class ConstraintSolver : public Component {
 public:
  // Solves at the end of the free motion. POS_AND_VEL: writes x_out and v_out;
  // VEL: v_out only. The solver's own dx vector receives the corrections.
  virtual void solve_constraint(const ConstraintParams& p, int x_out, int v_out) = 0;
  // Vector id holding the applied corrections (to project and propagate).
  virtual int dx_vec() const = 0;
  // The problem of the last solve (W, dfree, λ), for front ends; null when the
  // solver keeps none.
  virtual const ConstraintProblem* last_problem() const { return nullptr; }
};

}  // namespace sinew
