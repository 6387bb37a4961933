#include "solver/linear/pcg_linear_solver.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void PCGLinearSolver::init() {
  if (update_step.is_set())
    msg_warning("'update_step' is deprecated: use the assemblingRate of the PreconditionedMatrixFreeSystem");
  if (build_precond.is_set()) msg_warning("'build_precond' is deprecated and has no effect");

  // Linear system: the linked one, else the first unused PreconditionedMatrixFreeSystem
  // of this node or an ancestor, else a new one (spec/solvers.md §2.2).
  system_ = nullptr;
  if (linear_system) {
    system_ = dynamic_cast<PreconditionedMatrixFreeSystem*>(linear_system.get());
    if (!system_) {
      msg_error("the linear system " + linear_system->describe() + " is not a PreconditionedMatrixFreeSystem");
      set_state(ComponentState::invalid);
      return;
    }
  } else {
    bool other_system = false;
    for (Node* n = node(); n && !system_; n = n->parent())
      for (const auto& o : n->objects()) {
        if (auto* s = dynamic_cast<PreconditionedMatrixFreeSystem*>(o.get())) {
          if (!s->user) {
            system_ = s;
            break;
          }
        } else if (dynamic_cast<MatrixLinearSystem*>(o.get())) {
          other_system = true;
        }
      }
    if (!system_) {
      if (other_system)
        msg_warning("no linear system of type PreconditionedMatrixFreeSystem found (other linear systems exist); "
                    "a default one is created");
      else
        msg_info("no linear system found; a PreconditionedMatrixFreeSystem is created");
      auto sys = std::make_unique<PreconditionedMatrixFreeSystem>();
      sys->set_type("PreconditionedMatrixFreeSystem", "GraphScattered");
      sys->name.set("PreconditionedMatrixFreeSystem" +
                    std::to_string(node()->next_default_index("PreconditionedMatrixFreeSystem")));
      sys->where = where;
      system_ = static_cast<PreconditionedMatrixFreeSystem*>(node()->add_object(std::move(sys)));
    }
    linear_system.set(system_);
  }
  if (system_->user && system_->user != this)
    msg_warning("the linear system " + system_->describe() + " is already used by another solver");
  system_->user = this;

  precond_ = nullptr;
  if (!preconditioner.is_set() && !preconditioner) {
    msg_info("Link 'preconditioner' to the desired linear solver should be set to precondition the conjugate "
             "gradient. Without preconditioner, the solver will act as a regular conjugate gradient solver.");
  } else if (!preconditioner) {
    msg_error("No preconditioner found at path: " + preconditioner.path());
    set_state(ComponentState::invalid);
    return;
  } else {
    precond_ = dynamic_cast<MatrixLinearSolver*>(preconditioner.get());
    if (!precond_) {
      msg_error("Can not use the preconditioner " + preconditioner->describe() +
                " because it is templated on GraphScatteredType");
      set_state(ComponentState::invalid);
      return;
    }
  }
  r_ = MechanicalOps::alloc_vec();
  w_ = MechanicalOps::alloc_vec();
  s_ = MechanicalOps::alloc_vec();
  set_state(ComponentState::valid);
}

void PCGLinearSolver::bwd_init() {
  if (state() == ComponentState::invalid || !precond_ || !system_) return;
  // The preconditioner's matrix is assembled through the PCG's system.
  if (MatrixLinearSystem* ps = precond_->system()) system_->preconditioner_system.set(ps);
}

void PCGLinearSolver::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_begin) {
    newton_iter_ = 0;
    errors_.clear();
  }
}

void PCGLinearSolver::build_system(MechanicalOps& ops, double m, double b, double k) {
  if (state() == ComponentState::invalid || !system_) return;
  system_->build_system_matrix(ops, m, b, k);
}

void PCGLinearSolver::apply_preconditioner(MechanicalOps& ops, int z, int r) {
  MatrixLinearSystem& ps = *precond_->system();
  ps.set_system_solution(ops, z);
  ps.set_rhs(ops, r);
  precond_->solve_global(ps.solution(), ps.rhs());
  ps.dispatch_system_solution(ops, z);
}

void PCGLinearSolver::solve_system(MechanicalOps& ops, int x, int rhs) {
  if (state() == ComponentState::invalid || !system_) return;
  ++newton_iter_;
  errors_.clear();
  const PreconditionedMatrixFreeSystem& A = *system_;
  const bool apply_precond = precond_ && use_precond.value() && precond_->system();

  // Temporaries start at zero at every solve (SOFA allocates them per solve).
  ops.v_clear(r_);
  ops.v_clear(w_);
  ops.v_clear(s_);

  const double b_norm = ops.v_dot(rhs, rhs);
  const double tol = tolerance.value() * b_norm;

  A.product(ops, x, r_);           // r = A·x
  ops.v_op(r_, rhs, r_, -1.0);     // r = b + r·(−1)
  if (apply_precond) apply_preconditioner(ops, w_, r_);
  else ops.v_eq(w_, r_);

  double r_norm = ops.v_dot(r_, w_);
  errors_.push_back(r_norm / b_norm);

  unsigned iter = 1;
  const unsigned max_iter = iterations.value();
  while (iter <= max_iter && r_norm > tol) {
    A.product(ops, w_, s_);        // s = A·w
    const double dtq = ops.v_dot(w_, s_);
    const double alpha = r_norm / dtq;
    ops.v_peq(x, w_, alpha);       // x += α·w
    ops.v_peq(r_, s_, -alpha);     // r += (−α)·s
    if (apply_precond) apply_preconditioner(ops, s_, r_);
    else ops.v_eq(s_, r_);
    const double delta_old = r_norm;
    r_norm = ops.v_dot(r_, s_);
    errors_.push_back(r_norm / b_norm);
    const double beta = r_norm / delta_old;
    ops.v_op(w_, s_, w_, beta);    // w = s + w·β
    ++iter;
  }
  last_iterations_ = static_cast<int>(iter) - 1;
  if (!ops.all_finite(x)) {
    msg_error("the solution is not finite after " + std::to_string(last_iterations_) +
              " iterations (rᵀz / bᵀb = " + parse::format_double(r_norm / b_norm) +
              "): the system matrix or the preconditioner is singular or indefinite");
  }
}

void register_pcg_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "PCGLinearSolver";
  info.category = "LinearSolver/Iterative";
  info.description = "preconditioned conjugate gradient, matrix-free, warm-started from the previous solution";
  info.templates = {"GraphScattered"};
  info.default_template = "GraphScattered";
  info.create = creator<PCGLinearSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
