#include "forcefield/fem/element_fem_force_field.h"

#include <cmath>
#include <type_traits>

#include "core/init_checks.h"
#include "core/node.h"
#include "topology/mesh_topology.h"

namespace sinew {

FemElementKind fem_element_kind_from_template(const std::string& tmpl) {
  if (tmpl.find("Hexahedron") != std::string::npos) return FemElementKind::hexahedron;
  if (tmpl.find("Prism") != std::string::npos) return FemElementKind::prism;
  if (tmpl.find("Pyramid") != std::string::npos) return FemElementKind::pyramid;
  return FemElementKind::tetrahedron;
}

const char* fem_element_plural(FemElementKind kind) {
  switch (kind) {
    case FemElementKind::tetrahedron: return "tetrahedra";
    case FemElementKind::hexahedron: return "hexahedra";
    case FemElementKind::prism: return "prisms";
    case FemElementKind::pyramid: return "pyramids";
  }
  return "elements";
}

namespace {
// The topology's elements with N nodes (4: tetrahedra, 8: hexahedra, 6: prisms, 5: pyramids).
template <int N>
const std::vector<std::array<unsigned, N>>& element_list(const MeshTopologyBase& t) {
  if constexpr (N == 4) return t.tetrahedra();
  else if constexpr (N == 8) return t.hexahedra();
  else if constexpr (N == 6) return prisms_of(t);
  else return pyramids_of(t);
}
}  // namespace

bool ElementFEMForceFieldBase::read_strategy(const Field<std::string>& f, bool& parallel) {
  const std::string& v = f.get();
  if (v == "parallel") parallel = true;
  else if (v == "sequenced") parallel = false;
  else {
    msg_error(f.name() + " '" + v + "' is not valid (expected \"parallel\" or \"sequenced\")");
    return false;
  }
  return true;
}

void ElementFEMForceFieldBase::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  auto fail = [&](const std::string& m) {
    msg_error(m);
    set_state(ComponentState::invalid);
  };
  if (!require_vec3_state(*this) || !bind_node_topology(*this, topology, "link one with topology=\"@...\"")) return;
  MechanicalState& s = *mstate;

  bool par_f = true, par_df = true;
  if (!read_strategy(compute_force_strategy, par_f) || !read_strategy(compute_force_deriv_strategy, par_df))
    return fail("invalid compute strategy");
  fem::RotationMethod method;
  if (!rotation_method(method)) {
    set_state(ComponentState::invalid);
    return;
  }

  std::size_t ne = 0;
  visit_kernel([&](auto& kernel) { ne = element_list<std::decay_t<decltype(kernel)>::N>(*topology).size(); });
  if (ne == 0)
    return fail("the topology " + topology->describe() + " has no " + fem_element_plural(kind_));

  // Material per element: value i if given, else value 0 (SOFA's broadcast);
  // SOFA replaces E < 0 by 5000 and ν outside [0, 0.5) by 0.45, with a warning.
  std::vector<double> ey = young_modulus.get(), pr = poisson_ratio.get();
  if (ey.empty()) {
    msg_warning("'youngModulus' is empty: using the default value 5000");
    ey = {5000.0};
  }
  if (pr.empty()) {
    msg_warning("'poissonRatio' is empty: using the default value 0.45");
    pr = {0.45};
  }
  for (std::size_t i = 0; i < ey.size(); ++i) {
    if (ey[i] < 0 || !std::isfinite(ey[i])) {
      msg_warning("youngModulus of element " + std::to_string(i) + " is " + parse::format_double(ey[i]) +
                  ": Young's modulus must be positive, it is set to 5000");
      ey[i] = 5000.0;
    } else if (ey[i] == 0) {
      msg_warning("youngModulus of element " + std::to_string(i) + " is 0: the element has no stiffness");
    }
  }
  for (std::size_t i = 0; i < pr.size(); ++i)
    if (!(pr[i] >= 0 && pr[i] < 0.5)) {
      msg_warning("poissonRatio of element " + std::to_string(i) + " is " + parse::format_double(pr[i]) +
                  ": Poisson's ratio must be in [0, 0.5), it is set to 0.45");
      pr[i] = 0.45;
    }
  std::vector<double> E(ne), nu(ne);
  for (std::size_t i = 0; i < ne; ++i) {
    E[i] = i < ey.size() ? ey[i] : ey[0];
    nu[i] = i < pr.size() ? pr[i] : pr[0];
  }

  const std::span<const Vec3> X0 = as_vec3(s.read(kRestPosition));
  std::vector<fem::ElementIssue> issues;
  std::vector<double>& flat = element_stiffness.edit();
  flat.clear();
  visit_kernel([&](auto& kernel) {
    constexpr int N = std::decay_t<decltype(kernel)>::N;
    const auto& elems = element_list<N>(*topology);
    issues = kernel.init(X0, std::span<const std::array<unsigned, N>>(elems.data(), elems.size()), E, nu, method);
    kernel.parallel_force = par_f;
    kernel.parallel_dforce = par_df;
    flat.reserve(ne * 9 * N * N);
    for (const auto& k : kernel.K) flat.insert(flat.end(), k.begin(), k.end());
  });
  bool fatal = false;
  for (const auto& is : issues) {
    const std::string where = is.element >= 0 ? "element " + std::to_string(is.element) + ": " : "";
    if (is.fatal) {
      msg_error(where + is.message);
      fatal = true;
    } else {
      msg_warning(where + is.message);
    }
  }
  if (fatal) set_state(ComponentState::invalid);
}

void ElementFEMForceFieldBase::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::span<const Vec3> x = as_vec3(s.read(p.x));
  const std::span<const Vec3> X0 = as_vec3(s.read(kRestPosition));
  const std::span<Vec3> f = as_vec3(s.write(p.f));
  visit_kernel([&](auto& kernel) { kernel.add_force(x, X0, f); });
}

void ElementFEMForceFieldBase::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::span<const Vec3> dx = as_vec3(s.read(p.dx));
  const std::span<Vec3> df = as_vec3(s.write(p.df));
  visit_kernel([&](auto& kernel) { kernel.add_dforce(dx, df, kfactor); });
}

bool ElementFEMForceFieldBase::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  auto sink = [&](unsigned i, unsigned j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); };
  visit_kernel([&](const auto& kernel) { kernel.stiffness_blocks(sink); });
  return true;
}

}  // namespace sinew
