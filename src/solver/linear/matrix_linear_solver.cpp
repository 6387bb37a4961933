#include "solver/linear/matrix_linear_solver.h"

#include "core/node.h"

namespace sinew {

std::string MatrixLinearSolver::system_template() const {
  return template_name().empty() ? std::string("CompressedRowSparseMatrixd") : template_name();
}

void MatrixLinearSolver::init() {
  if (linear_system) {
    if (linear_system->user && linear_system->user != this)
      msg_warning("the linear system " + linear_system->describe() + " is already used by another solver");
    linear_system->user = this;
    return;
  }
  const std::string want = system_template();
  std::vector<MatrixLinearSystem*> candidates;
  bool any_system = false;
  for (Node* n = node(); n; n = n->parent())
    for (const auto& o : n->objects()) {
      auto* s = dynamic_cast<MatrixLinearSystem*>(o.get());
      if (!s) continue;
      any_system = true;
      const std::string st = s->template_name().empty() ? "CompressedRowSparseMatrixd" : s->template_name();
      if (st == want && !s->user) candidates.push_back(s);
    }
  if (!candidates.empty()) {
    if (candidates.size() > 1)
      msg_warning("several linear systems of type " + want + " are available; the first one (" +
                  candidates.front()->describe() + ") is used");
    linear_system.set(candidates.front());
    candidates.front()->user = this;
    return;
  }
  if (any_system)
    msg_warning("no linear system of type MatrixLinearSystem<" + want +
                "> found (other linear systems exist); a default one is created");
  else
    msg_info("no linear system found; a MatrixLinearSystem<" + want + "> is created");
  auto sys = std::make_unique<MatrixLinearSystem>();
  sys->set_type("MatrixLinearSystem", want);
  sys->name.set("MatrixLinearSystem" + std::to_string(node()->next_default_index("MatrixLinearSystem")));
  sys->where = where;
  auto* raw = static_cast<MatrixLinearSystem*>(node()->add_object(std::move(sys)));
  raw->user = this;
  linear_system.set(raw);
}

void MatrixLinearSolver::build_system(MechanicalOps& ops, double m, double b, double k) {
  ops.m_fact = m;
  ops.b_fact = b;
  ops.k_fact = k;
  if (linear_system) linear_system->build_system_matrix(ops, m, b, k);
}

void MatrixLinearSolver::solve_global(Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  MatrixLinearSystem& sys = *linear_system;
  if (sys.matrix_changed()) {
    invert(sys.matrix());
    sys.clear_matrix_changed();
  }
  solve(sys.matrix(), x, b);
}

void MatrixLinearSolver::add_jminvjt(Eigen::MatrixXd& result,
                                     const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J, double fact) {
  if (!linear_system) return;
  const Eigen::Index n = J.cols(), m = J.rows();
  if (result.rows() < m || result.cols() < m) result.conservativeResize(m, m);
  Eigen::VectorXd rhs(n), y(n);
  for (Eigen::Index row = 0; row < m; ++row) {
    if (J.outerIndexPtr()[row] == J.outerIndexPtr()[row + 1]) continue;
    rhs.setZero();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, row); it; ++it) rhs[it.col()] = it.value();
    y.setZero();
    solve_global(y, rhs);
    for (Eigen::Index r2 = 0; r2 < m; ++r2) {
      double acc = 0;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, r2); it; ++it)
        acc += it.value() * y[it.col()];
      result(r2, row) += fact * acc;
    }
  }
}

void MatrixLinearSolver::solve_system(MechanicalOps& ops, int x, int rhs) {
  if (!linear_system || !linear_system->assembled()) {
    msg_error("System matrix is not setup properly");
    return;
  }
  MatrixLinearSystem& sys = *linear_system;
  sys.set_system_solution(ops, x);
  sys.set_rhs(ops, rhs);
  solve_global(sys.solution(), sys.rhs());
  sys.dispatch_system_solution(ops, x);
}

}  // namespace sinew
