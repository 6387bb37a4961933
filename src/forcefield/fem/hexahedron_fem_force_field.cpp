#include "forcefield/fem/hexahedron_fem_force_field.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/grid/sparse_grid_topology.h"

namespace sinew {

void hexa_element_materials(const Component& c, const std::vector<double>& young,
                            const std::vector<double>& poisson, std::size_t ne, std::vector<double>& E,
                            std::vector<double>& nu) {
  E.resize(ne);
  nu.resize(ne);
  for (std::size_t i = 0; i < ne; ++i) {
    double e = young.empty() ? 5000.0 : (i < young.size() ? young[i] : young[0]);
    double v = poisson.empty() ? 0.45 : (i < poisson.size() ? poisson[i] : poisson[0]);
    if (!(e > 0)) {
      if (i < young.size() || i == 0)
        c.msg_warning("youngModulus of element " + std::to_string(i) + " is " + parse::format_double(e) +
                      (e < 0 ? ": replaced by 5000" : ": the element has no stiffness"));
      if (e < 0) e = 5000.0;
    }
    if (v < 0 || v >= 0.5) {
      if (i < poisson.size() || i == 0)
        c.msg_warning("poissonRatio of element " + std::to_string(i) + " is " + parse::format_double(v) +
                      " (must be in [0, 0.5)): replaced by 0.45");
      v = 0.45;
    }
    E[i] = e;
    nu[i] = v;
  }
}

double hexa_mass_integral(double density) {
  const double t1 = 1, t2 = 1, t3 = 1, t9 = t1 * t2;
  return (t1 * t3 / 72.0 + t2 * t3 / 72.0 + t9 * t3 / 216.0 + t3 / 24.0 + 1.0 / 8.0 + t9 / 72.0 + t1 / 24.0 +
          t2 / 24.0) *
         density;
}

template <class Role>
void HexahedronFEMBase<Role>::init() {
  Role::init();
  if (this->state() != ComponentState::valid) return;
  if (!topology) topology.set(this->node()->get_mesh_topology_link());
  if (!topology) {
    this->msg_error("no topology found (a hexahedral mesh is required)");
    this->set_state(ComponentState::invalid);
    return;
  }
  const auto& hexas = topology->hexahedra();
  hexa_version_ = topology->elements_version(MeshTopologyBase::Elements::hexahedra);
  if (hexas.empty()) {
    this->msg_error("the topology " + topology->describe() + " has no hexahedra");
    this->set_state(ComponentState::invalid);
    return;
  }
  fem::HexaMethod m;
  if (method.value() == "large") m = fem::HexaMethod::large;
  else if (method.value() == "polar") m = fem::HexaMethod::polar;
  else if (method.value() == "small") m = fem::HexaMethod::small;
  else {
    this->msg_error("unknown method '" + method.value() + "' (expected large, polar or small)");
    this->set_state(ComponentState::invalid);
    return;
  }
  const std::size_t ne = hexas.size();
  std::vector<double> E, nu;
  hexa_element_materials(*this, young_modulus.get(), poisson_ratio.get(), ne, E, nu);
  MechanicalState& s = *this->mstate;
  if (s.state_type() != StateType::vec3) {
    this->msg_error("only Vec3d states are supported");
    this->set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& x0 = s.read(kRestPosition);
  std::vector<std::array<int, 8>> h(ne);
  for (std::size_t i = 0; i < ne; ++i)
    for (int k = 0; k < 8; ++k) h[i][k] = static_cast<int>(hexas[i][k]);
  rest_.assign(as_vec3(x0).begin(), as_vec3(x0).end());
  fem_.update_stiffness = update_stiffness_matrix.value();
  // On a sparse grid each element's stiffness is scaled by the grid's filling
  // coefficient (0.5 on boundary cells, averaged over virtual finer levels).
  std::vector<double> stiffness_coef;
  if (const auto* grid = dynamic_cast<const SparseGridTopology*>(topology.get()))
    for (std::size_t i = 0; i < ne; ++i) stiffness_coef.push_back(grid->stiffness_coef(i));
  const auto issues = fem_.init(as_vec3(x0), h, E, nu, m, stiffness_coef);
  bool fatal = false;
  for (const auto& is : issues) {
    const std::string where = is.element >= 0 ? "element " + std::to_string(is.element) + ": " : "";
    if (is.fatal) {
      this->msg_error(where + is.message);
      fatal = true;
    } else {
      this->msg_warning(where + is.message);
    }
  }
  if (fatal) this->set_state(ComponentState::invalid);
}

template <class Role>
void HexahedronFEMBase<Role>::follow_topology() {
  if (!topology || topology->elements_version(MeshTopologyBase::Elements::hexahedra) == hexa_version_) return;
  hexa_version_ = topology->elements_version(MeshTopologyBase::Elements::hexahedra);
  const auto& live = topology->hexahedra();
  std::size_t n = live.size();
  if (n > fem_.active.size()) {
    // SOFA would read its per-element arrays past their end: the added hexahedra are not simulated.
    if (!warned_growth_)
      this->msg_warning("hexahedra were added after init: as SOFA has no data for them, they add no force");
    warned_growth_ = true;
    n = fem_.active.size();
  }
  const std::size_t np = this->mstate->size();
  fem_.hexa.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    bool in_range = true;
    for (int k = 0; k < 8; ++k) {
      fem_.hexa[e][k] = static_cast<int>(live[e][k]);
      in_range = in_range && live[e][k] < np;
    }
    fem_.active[e] = in_range ? 1 : 0;
  }
  fem_.build_incidence(np);
}

template <class Role>
void HexahedronFEMBase<Role>::add_force(const MechParams& p) {
  follow_topology();
  MechanicalState& s = *this->mstate;
  const std::vector<double>& x = s.read(p.x);
  std::vector<double>& f = s.write(p.f);
  fem_.add_force(as_vec3(x), as_vec3(f));
}

template <class Role>
void HexahedronFEMBase<Role>::add_dforce(const MechParams& p, double kfactor) {
  follow_topology();
  MechanicalState& s = *this->mstate;
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  fem_.add_dforce(as_vec3(dx), as_vec3(df), kfactor);
}

template <class Role>
bool HexahedronFEMBase<Role>::build_stiffness(MatrixSink& K) {
  follow_topology();
  const MechanicalState* s = this->mstate.get();
  // ∂f/∂x blocks −Rᵀ·K_ij·R (kfactor 1); the assembler applies its factor.
  fem_.add_stiffness_blocks(1.0, [&](int i, int j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
  return true;
}

// ---------------------------------------------------------------- AndMass

void HexahedronFEMForceFieldAndMass::init() {
  HexahedronFEMBase<Mass>::init();
  if (state() != ComponentState::valid) return;
  const std::size_t ne = fem_.size(), np = rest_.size();
  const double rho = density.value();
  const double integral = hexa_mass_integral(rho);
  element_mass_.assign(ne, 0.0);
  particle_mass_.assign(np, 0.0);
  // On a sparse grid both masses are scaled by the grid's filling coefficient.
  const auto* grid = dynamic_cast<const SparseGridTopology*>(topology.get());
  for (std::size_t e = 0; e < ne; ++e) {
    const double coef = grid ? static_cast<double>(grid->mass_coef(e)) : 1.0;
    const auto& n = fem_.rest[e];  // rotated rest element
    const double vol = (n[1] - n[0]).norm() * (n[3] - n[0]).norm() * (n[4] - n[0]).norm();
    element_mass_[e] = vol * integral;
    if (grid) element_mass_[e] *= coef;
    // Gravity uses the physical mass of the unrotated element, an eighth per corner.
    const auto& h = fem_.hexa[e];
    double v0 = (rest_[h[1]] - rest_[h[0]]).norm() * (rest_[h[3]] - rest_[h[0]]).norm() *
                (rest_[h[4]] - rest_[h[0]]).norm();
    if (grid) v0 *= coef;
    const double m = (v0 * rho) / 8.0;
    for (int w = 0; w < 8; ++w) particle_mass_[h[w]] += m;
  }
  lumped_.clear();
  if (lumped_mass.value()) {
    lumped_.assign(np, Vec3::Zero());
    for (std::size_t e = 0; e < ne; ++e)
      for (int w = 0; w < 8; ++w)
        for (int j = 0; j < 8; ++j)  // row sums: the 8 non-zero entries of each row
          for (int c = 0; c < 3; ++c) lumped_[fem_.hexa[e][w]][c] += element_mass_[e];
  }
}

void HexahedronFEMForceFieldAndMass::add_force(const MechParams& p) {
  HexahedronFEMBase<Mass>::add_force(p);
  // SOFA adds gravity here whatever separateGravity says.
  auto f = as_vec3(mstate->write(p.f));
  const Vec3 g = node()->gravity.value();
  for (std::size_t i = 0; i < particle_mass_.size(); ++i) f[i] += g * particle_mass_[i];
}

namespace {
// f += factor·M·d over the elements, M_e = N_e ⊗ I3 with N_e(w, j) = mass(e, w, j). Row (w, c):
// SOFA's 24 products in column order, of which only the 8 on component c are nonzero (the
// others add exact zeros, dropped here).
template <class NodalMass>
void add_element_mdx(const fem::HexaFEM& fem, std::span<const Vec3> d, std::span<Vec3> f, double factor,
                     NodalMass mass) {
  for (std::size_t e = 0; e < fem.size(); ++e) {
    const auto& h = fem.hexa[e];
    for (int w = 0; w < 8; ++w) {
      Vec3 F = Vec3::Zero();
      for (int c = 0; c < 3; ++c) {
        double s = 0.0;
        for (int j = 0; j < 8; ++j) s += mass(e, c, w, j) * d[h[j]][c];
        F[c] = s;
      }
      f[h[w]] += F * factor;
    }
  }
}
}  // namespace

void HexahedronFEMForceFieldAndMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  auto f = as_vec3(mstate->write(res));
  const auto d = as_vec3(mstate->read(dx));
  if (lumped_mass.value()) {
    for (std::size_t i = 0; i < lumped_.size(); ++i)
      for (int c = 0; c < 3; ++c) f[i][c] += lumped_[i][c] * d[i][c] * factor;
    return;
  }
  if (!component_mass_.empty())
    add_element_mdx(fem_, d, f, factor,
                    [&](std::size_t e, int c, int w, int j) { return component_mass_[e][c][8 * w + j]; });
  else if (!nodal_mass_.empty())
    add_element_mdx(fem_, d, f, factor, [&](std::size_t e, int, int w, int j) { return nodal_mass_[e][8 * w + j]; });
  else
    add_element_mdx(fem_, d, f, factor, [&](std::size_t e, int, int, int) { return element_mass_[e]; });
}

void HexahedronFEMForceFieldAndMass::acc_from_f(const MechParams&, int, int) {
  msg_warning("accFromF is not available (the element mass matrices are not diagonal); use an implicit solver");
}

void HexahedronFEMForceFieldAndMass::add_gravity_to_v(int v, double dt) {
  auto vv = as_vec3(mstate->write(v));
  const Vec3 dv = node()->gravity.value() * dt;
  for (auto& x : vv) x += dv;
}

bool HexahedronFEMForceFieldAndMass::build_mass(MatrixSink& M) {
  const MechanicalState* s = mstate.get();
  for (std::size_t e = 0; e < fem_.size(); ++e) {
    const auto& h = fem_.hexa[e];
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        if (!component_mass_.empty()) {
          Mat3 b = Mat3::Zero();
          for (int c = 0; c < 3; ++c) b(c, c) = component_mass_[e][c][8 * i + j];
          M.add_block(s, 3 * h[i], s, 3 * h[j], b);
          continue;
        }
        const double m = nodal_mass_.empty() ? element_mass_[e] : nodal_mass_[e][8 * i + j];
        M.add_block(s, 3 * h[i], s, 3 * h[j], Mat3::Identity() * m);
      }
  }
  return true;
}

double HexahedronFEMForceFieldAndMass::total() const {
  double t = 0;
  for (double m : particle_mass_) t += m;
  return t;
}

template class HexahedronFEMBase<ForceField>;
template class HexahedronFEMBase<Mass>;

void register_hexahedron_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "hexahedral finite elements, corotational (large, polar) or linear (small)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedronFEMForceField>();
  r.add(std::move(info));
}

void register_hexahedron_fem_force_field_and_mass(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronFEMForceFieldAndMass";
  info.category = "ForceField/FEM";
  info.description = "hexahedral finite elements that are also the mass of their object";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedronFEMForceFieldAndMass>();
  r.add(std::move(info));
}

}  // namespace sinew
