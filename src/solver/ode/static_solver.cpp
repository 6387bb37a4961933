#include "solver/ode/static_solver.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
class StaticFunction final : public NonlinearFunction {
 public:
  StaticFunction(MechanicalOps& ops, LinearSolver& ls, int x, int dx) : ops_(ops), ls_(ls), x_(x), dx_(dx) {}
  double evaluate() override {
    ops_.compute_force(kForce, true, true, x_, kVelocity);
    ops_.project_response(kForce);
    return ops_.v_dot(kForce, kForce);
  }
  void solve_linear_step() override {
    ls_.build_system(ops_, 0.0, 0.0, -1.0);
    ls_.solve_system(ops_, dx_, kForce);
  }
  void update(double alpha) override {
    for (MechanicalState* s : ops_.independent_states()) s->add_deriv_to_coord(x_, x_, dx_, alpha);
    ops_.propagate_x_and_v(x_, kVelocity);
  }
  double dx_norm2() override { return ops_.v_dot(dx_, dx_); }
  double x_norm2() override {
    double n = 0;
    for (MechanicalState* s : ops_.independent_states())
      for (double v : s->read(x_)) n += v * v;
    return n;
  }

 private:
  MechanicalOps& ops_;
  LinearSolver& ls_;
  int x_, dx_;
};
}  // namespace

void StaticSolver::parse(AttributeMap& attrs, Diagnostics& diag) {
  const std::pair<const char*, const char*> renamed[] = {
      {"newton_iterations", "maxNbIterationsNewton"},
      {"absolute_correction_tolerance_threshold", "absoluteEstimateDifferenceThreshold"},
      {"relative_correction_tolerance_threshold", "relativeEstimateDifferenceThreshold"},
      {"absolute_residual_tolerance_threshold", "absoluteResidualStoppingThreshold"},
      // SOFA forwards this one to relativeEstimateDifferenceThreshold too.
      {"relative_residual_tolerance_threshold", "relativeEstimateDifferenceThreshold"},
  };
  for (const auto& [old_name, new_name] : renamed)
    if (const std::string* v = attrs.take(old_name)) {
      diag.warning(where, describe() + ": '" + old_name + "' is deprecated; set '" + new_name +
                              "' on a NewtonRaphsonSolver");
      forwarded_.emplace_back(new_name, *v);
    }
  if (attrs.take("should_diverge_when_residual_is_growing"))
    diag.warning(where, describe() + ": 'should_diverge_when_residual_is_growing' has been removed");
  OdeSolver::parse(attrs, diag);
}

void StaticSolver::init() {
  if (!linear_solver) linear_solver.set(node()->find_down<LinearSolver>());
  if (!linear_solver) {
    msg_error("no linear solver found in this node or below it");
    set_state(ComponentState::invalid);
    return;
  }
  if (!newton_solver) newton_solver.set(node()->find_down<NewtonRaphsonSolver>());
  if (!newton_solver) {
    msg_warning("no NewtonRaphsonSolver found: one is created with default settings");
    auto created = std::make_unique<NewtonRaphsonSolver>();
    created->set_type("NewtonRaphsonSolver", {});
    created->name.set("NewtonRaphsonSolver");
    created->where = where;
    newton_solver.set(static_cast<NewtonRaphsonSolver*>(node()->add_object(std::move(created))));
  }
  for (const auto& [field, value] : forwarded_)
    if (BaseField* f = newton_solver->find_field(field)) f->read(value);
  dx_ = MechanicalOps::alloc_vec();
}

void StaticSolver::solve(double, int x_result, int) {
  MechanicalOps& ops = scope();
  if (x_result != kPosition) ops.v_eq(x_result, kPosition);
  StaticFunction fn(ops, *linear_solver, x_result, dx_);
  newton_solver->solve(fn);
}

void register_static_solver(Registry& r) {
  ComponentInfo info;
  info.name = "StaticSolver";
  info.category = "Solver/ODE";
  info.description = "static equilibrium by Newton-Raphson (velocities untouched)";
  info.create = creator<StaticSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
