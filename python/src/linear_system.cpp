// SofaPython3's SofaLinearSystem and SofaLinearSolver modules: the global
// system A·x = b a matrix linear system assembled in the last solve.
//
// A is what the solver used: m·M + b·B + k·K of the system's scope with the
// projective constraints applied when the system applies them (a fixed DoF's
// row and column cleared, 1 on the diagonal). Sparse templates give a
// scipy.sparse CSR matrix of the exactly non-zero entries (SOFA copies a
// block matrix's non-zeros the same way; for the scalar CompressedRowSparseMatrixd
// SOFA also keeps the zeros it stored, so its nnz may be larger, never its
// values); FullMatrix gives a dense numpy array. b and x are numpy copies
// (they change with every solve).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>

#include "graph.h"
#include "handles.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/matrix_linear_system.h"

namespace sinew::python {

namespace {

struct LinearSystemHandle : ObjectHandle {
  MatrixLinearSystem& system() const { return static_cast<MatrixLinearSystem&>(component()); }
};
struct LinearSolverHandle : ObjectHandle {
  MatrixLinearSystem& system() const {
    auto& solver = static_cast<MatrixLinearSolver&>(component());
    MatrixLinearSystem* s = solver.system();
    if (!s) throw py::value_error(solver.describe() + " has no linear system (not initialised yet?)");
    return *s;
  }
};

ObjectHandle* make_handle(Component& c) {
  if (dynamic_cast<MatrixLinearSystem*>(&c)) return new LinearSystemHandle{};
  if (dynamic_cast<MatrixLinearSolver*>(&c)) return new LinearSolverHandle{};
  return nullptr;
}

py::object system_matrix(const MatrixLinearSystem& s) {
  const BlockCsrMatrix& A = s.matrix();
  if (s.template_name() == "FullMatrix") return py::cast(A.to_dense());
  std::vector<int> rb, ci;
  std::vector<double> v;
  A.to_filtered_csr(rb, ci, v);
  return scipy_csr(v, ci, rb, A.size(), A.size());
}

py::array_t<double> vector_copy(const Eigen::VectorXd& v) { return py::array_t<double>(v.size(), v.data()); }

template <class Handle>
void define_access(py::class_<Handle, ObjectHandle>& c, bool long_names) {
  auto A = [](Handle& h) { return system_matrix(h.system()); };
  auto b = [](Handle& h) { return vector_copy(h.system().rhs()); };
  auto x = [](Handle& h) { return vector_copy(h.system().solution()); };
  c.def("A", A, "Global system matrix of the last solve (scipy.sparse CSR; numpy for FullMatrix)");
  c.def("b", b, "Right-hand side of the last solve (numpy)");
  c.def("x", x, "Solution of the last solve (numpy)");
  if (!long_names) return;
  c.def("get_system_matrix", A, "Global system matrix of the last solve (scipy.sparse CSR; numpy for FullMatrix)");
  c.def("get_rhs_vector", b, "Right-hand side of the last solve (numpy)");
  c.def("get_solution_vector", x, "Solution of the last solve (numpy)");
}

}  // namespace

void define_linear_system(py::module_& m) {
  py::class_<LinearSystemHandle, ObjectHandle> system(m, "MatrixLinearSystem",
                                                      "An assembled linear system (any matrix template)");
  define_access(system, true);
  py::class_<LinearSolverHandle, ObjectHandle> solver(m, "MatrixLinearSolver",
                                                      "A linear solver working on an assembled system");
  define_access(solver, false);  // SofaPython3's solver binding has the short names only
  register_handle_maker(&make_handle);
}

}  // namespace sinew::python
