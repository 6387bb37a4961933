// Matrix access as SofaPython3 gives it: assembleKMatrix on force fields and
// assembleMMatrix on masses, as scipy.sparse CSR matrices of the component's
// state (one row and column per scalar degree of freedom).
#include <pybind11/numpy.h>

#include <algorithm>
#include <tuple>

#include "core/matrix_sink.h"
#include "core/roles.h"
#include "graph.h"
#include "handles.h"

namespace sinew::python {

namespace {

py::object to_csr(const MatrixSink& sink, const MechanicalState& s) {
  const std::size_t n = s.size() * static_cast<std::size_t>(s.info().deriv_width);
  // Sorted (row, col) with duplicates summed: the CSR arrays scipy expects.
  std::vector<std::tuple<std::uint32_t, std::uint32_t, double>> t;
  t.reserve(sink.entries().size());
  for (const auto& e : sink.entries())
    if (e.row_state == &s && e.col_state == &s) t.emplace_back(e.row, e.col, e.value);
  std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) < std::get<0>(b) : std::get<1>(a) < std::get<1>(b);
  });
  std::vector<double> values;
  std::vector<std::int32_t> cols, rows(n + 1, 0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto [r, c, v] = t[i];
    if (!values.empty() && i > 0 && std::get<0>(t[i - 1]) == r && std::get<1>(t[i - 1]) == c) {
      values.back() += v;
      continue;
    }
    values.push_back(v);
    cols.push_back(static_cast<std::int32_t>(c));
    ++rows[r + 1];
  }
  for (std::size_t r = 0; r < n; ++r) rows[r + 1] += rows[r];
  return scipy_csr(values, cols, rows, n, n);
}

MechanicalState& state_of(ForceField& ff) {
  MechanicalState* s = ff.single_state();
  if (!s) throw py::value_error(ff.describe() + " acts on " + std::to_string(ff.states().size()) +
                                " states (or none): its matrix has no single state to be expressed in");
  return *s;
}

// SofaPython3's mass classes (Sofa.Core.BaseMass, MassVec3d, MassRigid3d...):
// the Python type of a mass follows its state's type, known when it is first
// handed to Python if its state was added before it (the usual order);
// otherwise it is a BaseMass.
struct BaseMassHandle : ObjectHandle {};
template <StateType T>
struct MassHandle : BaseMassHandle {};

ObjectHandle* make_mass_handle(Component& c) {
  auto* mass = dynamic_cast<Mass*>(&c);
  if (!mass) return nullptr;
  const MechanicalState* s = mass->mstate.get();
  if (!s && mass->node()) s = mass->node()->mechanical_state;
  if (!s) return new BaseMassHandle{};
  switch (s->state_type()) {
    case StateType::vec1: return new MassHandle<StateType::vec1>{};
    case StateType::vec2: return new MassHandle<StateType::vec2>{};
    case StateType::vec3: return new MassHandle<StateType::vec3>{};
    case StateType::vec6: return new MassHandle<StateType::vec6>{};
    case StateType::rigid2: return new MassHandle<StateType::rigid2>{};
    case StateType::rigid3: return new MassHandle<StateType::rigid3>{};
  }
  return new BaseMassHandle{};
}

template <StateType T>
void define_mass(py::module_& m) {
  const std::string name = std::string("Mass") + state_type_info(T).name;
  py::class_<MassHandle<T>, BaseMassHandle>(m, name.c_str(), "A mass on a state of that type");
}

}  // namespace

py::object scipy_csr(const std::vector<double>& values, const std::vector<std::int32_t>& cols,
                     const std::vector<std::int32_t>& row_begin, std::size_t n_rows, std::size_t n_cols) {
  py::module_ sparse = py::module_::import("scipy.sparse");
  py::array_t<double> pv(values.size(), values.data());
  py::array_t<std::int32_t> pc(cols.size(), cols.data());
  py::array_t<std::int32_t> pr(row_begin.size(), row_begin.data());
  return sparse.attr("csr_matrix")(py::make_tuple(pv, pc, pr), py::arg("shape") = py::make_tuple(n_rows, n_cols));
}

void define_matrix_access(py::module_& m) {
  auto object = py::reinterpret_borrow<py::object>(m.attr("Object"));
  object.attr("assembleKMatrix") = py::cpp_function(
      [](ObjectHandle& h) {
        auto* ff = dynamic_cast<ForceField*>(&h.component());
        if (!ff) throw py::type_error(h.component().describe() + " is not a force field");
        MechanicalState& s = state_of(*ff);
        MatrixSink K;
        K.set_factor(1.0);
        if (!ff->build_stiffness(K)) throw py::value_error(ff->describe() + " cannot assemble its stiffness matrix");
        return to_csr(K, s);
      },
      py::is_method(object), py::name("assembleKMatrix"),
      py::doc("Stiffness matrix K = ∂f/∂x of this force field on its state (scipy.sparse CSR)"));
  object.attr("assembleMMatrix") = py::cpp_function(
      [](ObjectHandle& h) {
        auto* mass = dynamic_cast<Mass*>(&h.component());
        if (!mass) throw py::type_error(h.component().describe() + " is not a mass");
        MechanicalState& s = state_of(*mass);
        MatrixSink M;
        M.set_factor(1.0);
        if (!mass->build_mass(M)) throw py::value_error(mass->describe() + " cannot assemble its mass matrix");
        return to_csr(M, s);
      },
      py::is_method(object), py::name("assembleMMatrix"),
      py::doc("Mass matrix of this mass on its state (scipy.sparse CSR)"));

  py::class_<BaseMassHandle, ObjectHandle>(m, "BaseMass", "A mass (SOFA's BaseMass)");
  define_mass<StateType::vec3>(m);
  define_mass<StateType::vec2>(m);
  define_mass<StateType::vec1>(m);
  define_mass<StateType::vec6>(m);
  define_mass<StateType::rigid3>(m);
  define_mass<StateType::rigid2>(m);
  register_handle_maker(&make_mass_handle);
}

}  // namespace sinew::python
