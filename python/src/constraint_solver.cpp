// SofaPython3's SofaConstraintSolver module: the constraint problem of a
// constraint solver's last solve. W (the compliance in constraint space,
// n×n), dfree (the violation at the free motion) and lambda_force() (λ) are
// numpy copies: the solver reuses its storage every step. Read them in
// onBuildConstraintSystemEndEvent (W, dfree) or onSolveConstraintSystemEndEvent
// (λ too), or after the step.
#include <pybind11/numpy.h>

#include "core/constraint_problem.h"
#include "graph.h"
#include "handles.h"

namespace sinew::python {

namespace {

struct ConstraintSolverHandle : ObjectHandle {
  const ConstraintProblem& problem() const {
    auto& s = static_cast<ConstraintSolver&>(component());
    const ConstraintProblem* p = s.last_problem();
    if (!p) throw py::value_error(s.describe() + " keeps no constraint problem");
    return *p;
  }
};

ObjectHandle* make_handle(Component& c) {
  return dynamic_cast<ConstraintSolver*>(&c) ? new ConstraintSolverHandle{} : nullptr;
}

py::array_t<double> copy(const std::vector<double>& v, std::size_t n) {
  return py::array_t<double>(static_cast<py::ssize_t>(std::min(n, v.size())), v.data());
}

}  // namespace

void define_constraint_solver(py::module_& m) {
  py::class_<ConstraintSolverHandle, ObjectHandle>(m, "ConstraintSolver",
                                                   "A Lagrangian constraint solver and its last problem")
      .def(
          "W",
          [](ConstraintSolverHandle& h) {
            const ConstraintProblem& p = h.problem();
            const auto n = static_cast<py::ssize_t>(p.n);
            py::array_t<double> W({n, n});
            if (n > 0) std::copy(p.W.begin(), p.W.begin() + n * n, W.mutable_data());
            return W;
          },
          "Compliance matrix in constraint space of the last solve (numpy n×n)")
      .def(
          "lambda_force", [](ConstraintSolverHandle& h) { return copy(h.problem().f, h.problem().n); },
          "Constraint forces λ of the last solve (numpy, one per constraint row)")
      .def(
          "dfree", [](ConstraintSolverHandle& h) { return copy(h.problem().dfree, h.problem().n); },
          "Constraint violation at the free motion of the last solve (numpy, one per row)");
  register_handle_maker(&make_handle);
}

}  // namespace sinew::python
