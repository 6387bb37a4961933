#include "solver/preconditioner/warp_preconditioner.h"

#include <vector>

#include <Eigen/SparseCore>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void WarpPreconditioner::init() {
  if (use_rotation_finder.is_set()) msg_warning("'useRotationFinder' is deprecated and has no effect");
  if (update_step.is_set())
    msg_warning("'update_step' is deprecated: use the assemblingRate of the RotationMatrixSystem");
  if (!linear_system) {
    // The first unused RotationMatrixSystem of this node or an ancestor, else a new one.
    RotationMatrixSystem* found = nullptr;
    for (Node* n = node(); n && !found; n = n->parent())
      for (const auto& o : n->objects())
        if (auto* s = dynamic_cast<RotationMatrixSystem*>(o.get()); s && !s->user) {
          found = s;
          break;
        }
    if (!found) {
      msg_info("no linear system found; a RotationMatrixSystem is created");
      auto sys = std::make_unique<RotationMatrixSystem>();
      sys->set_type("RotationMatrixSystem", "RotationMatrixd");
      sys->name.set("RotationMatrixSystem" + std::to_string(node()->next_default_index("RotationMatrixSystem")));
      sys->where = where;
      found = static_cast<RotationMatrixSystem*>(node()->add_object(std::move(sys)));
    }
    linear_system.set(found);
  }
  MatrixLinearSolver::init();
  rotations_ = dynamic_cast<RotationMatrixSystem*>(linear_system.get());
  if (!rotations_) {
    msg_error("the linear system " + linear_system->describe() + " is not a RotationMatrixSystem");
    set_state(ComponentState::invalid);
  }
}

void WarpPreconditioner::bwd_init() {
  if (state() == ComponentState::invalid) return;
  if (!linear_solver) {
    msg_info("Link \"linearSolver\" to the desired linear solver should be set to ensure right behavior. First "
             "LinearSolver found in current context will be used.");
    for (LinearSolver* s : node()->linear_solvers)
      if (s != this) {
        linear_solver.set(s);
        break;
      }
  }
  if (!linear_solver) {
    msg_error("No LinearSolver component found at path '" + linear_solver.path() + "', nor in the current context " +
              node()->describe());
    set_state(ComponentState::invalid);
    return;
  }
  inner_ = dynamic_cast<MatrixLinearSolver*>(linear_solver.get());
  if (!inner_ || inner_ == this) {
    msg_error("Can not use the solver " + linear_solver->describe() + " because it is templated on GraphScatteredType");
    set_state(ComponentState::invalid);
    inner_ = nullptr;
    return;
  }
  if (!inner_->system()) {
    msg_error("the solver " + linear_solver->describe() + " has no linear system");
    set_state(ComponentState::invalid);
    inner_ = nullptr;
  }
}

void WarpPreconditioner::solve(const BlockCsrMatrix&, Eigen::VectorXd& z, const Eigen::VectorXd& r) {
  const Eigen::Index n = r.size();
  if (z.size() != n) z.setZero(n);
  if (state() == ComponentState::invalid || !inner_ || !rotations_) return;
  MatrixLinearSystem& sys = *inner_->system();
  if (!sys.assembled() || static_cast<Eigen::Index>(sys.size()) != n) {
    if (!warned_) {
      warned_ = true;
      msg_error("the system of " + inner_->describe() + " is not assembled (size " + std::to_string(sys.size()) +
                ", expected " + std::to_string(n) + "); the preconditioner returns 0");
    }
    z.setZero();
    return;
  }
  Eigen::VectorXd& rhs = sys.rhs();
  Eigen::VectorXd& sol = sys.solution();
  if (rhs.size() != n) rhs.setZero(n);
  if (sol.size() != n) sol.setZero(n);
  // rhs = Rᵀ·r
  const std::size_t nb = static_cast<std::size_t>(n) / 3;
  const bool blocks = rotations_->block(0) != nullptr;
  if (blocks) {
    for (std::size_t k = 0; k < nb; ++k) {
      const double* R = rotations_->block(k);
      const Eigen::Index o = static_cast<Eigen::Index>(3 * k);
      for (int c = 0; c < 3; ++c) rhs[o + c] = R[0 * 3 + c] * r[o] + R[1 * 3 + c] * r[o + 1] + R[2 * 3 + c] * r[o + 2];
    }
  } else {
    rhs = r;
  }
  inner_->solve_global(sol, rhs);
  // z = R·sol
  if (blocks) {
    for (std::size_t k = 0; k < nb; ++k) {
      const double* R = rotations_->block(k);
      const Eigen::Index o = static_cast<Eigen::Index>(3 * k);
      for (int c = 0; c < 3; ++c)
        z[o + c] = R[c * 3 + 0] * sol[o] + R[c * 3 + 1] * sol[o + 1] + R[c * 3 + 2] * sol[o + 2];
    }
  } else {
    z = sol;
  }
}

void WarpPreconditioner::add_jminvjt(Eigen::MatrixXd& result,
                                     const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J, double fact) {
  if (J.rows() == 0 || !inner_ || !rotations_) return;
  using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  const Eigen::Index n = J.cols();
  std::vector<Eigen::Triplet<double, int>> tr;
  const bool blocks = rotations_->block(0) != nullptr;
  for (Eigen::Index k = 0; k < n / 3; ++k) {
    const double* R = blocks ? rotations_->block(static_cast<std::size_t>(k)) : nullptr;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double v = R ? R[i * 3 + j] : (i == j ? 1.0 : 0.0);
        if (v != 0.0) tr.emplace_back(static_cast<int>(3 * k + i), static_cast<int>(3 * k + j), v);
      }
  }
  for (Eigen::Index i = (n / 3) * 3; i < n; ++i) tr.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
  RowSparse R(static_cast<int>(n), static_cast<int>(n));
  R.setFromTriplets(tr.begin(), tr.end());
  const RowSparse JR = J * R;
  inner_->add_jminvjt(result, JR, fact);
}

void register_warp_preconditioner(Registry& r) {
  ComponentInfo info;
  info.name = "WarpPreconditioner";
  info.category = "LinearSolver/Preconditioner";
  info.description = "rotates the residual into the frame of a direct solver's last assembled matrix: z = R·A⁻¹·Rᵀ·r";
  info.templates = {"RotationMatrixd"};
  info.default_template = "RotationMatrixd";
  info.create = creator<WarpPreconditioner>();
  r.add(std::move(info));
}

}  // namespace sinew
