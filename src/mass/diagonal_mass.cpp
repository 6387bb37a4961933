#include "mass/diagonal_mass.h"

#include <limits>

#include "core/node.h"
#include "core/registry.h"
#include "mass/diagonal_rigid_mass.h"
#include "mass/mesh_geometry.h"

namespace sinew {

using meshgeo::MassElement;

DiagonalMass::DiagonalMass() { file_mass.add_alias("fileMass"); }

double DiagonalMass::compute_vertex_mass(double rho) {
  MechanicalState& s = *mstate;
  MechanicalState& g = *geometry_state;
  const std::vector<double>& X = g.read(compute_mass_on_rest.get() ? kRestPosition : kPosition);
  const int w = g.info().coord_width;
  std::vector<double> m(s.size(), 0.0);
  double total = 0;
  const MeshTopologyBase& t = *topology;
  auto add = [&](auto const& elem, double mass) {
    for (unsigned i : elem) {
      m[i] += mass;
      total += mass;
    }
  };
  switch (static_cast<MassElement>(kind_)) {
    case MassElement::edge:
      for (const Edge& e : t.edges()) add(e, (rho * meshgeo::edge_length(X, w, e[0], e[1])) / 2.0);
      break;
    case MassElement::triangle:
      for (const Triangle& e : t.triangles()) add(e, (rho * meshgeo::triangle_area(X, w, e[0], e[1], e[2])) / 3.0);
      break;
    case MassElement::quad:
      for (const Quad& e : t.quads()) add(e, (rho * meshgeo::quad_area(X, w, e)) / 4.0);
      break;
    case MassElement::tetra:
      for (const Tetra& e : t.tetrahedra()) add(e, (rho * meshgeo::tetra_volume(X, e[0], e[1], e[2], e[3])) / 4.0);
      break;
    case MassElement::hexa:
      for (const Hexa& e : t.hexahedra()) add(e, (rho * meshgeo::hexa_volume(X, e)) / 8.0);
      break;
    case MassElement::none:
      break;
  }
  vertex_mass.set(std::move(m));
  return total;
}

void DiagonalMass::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  if (!file_mass.get().empty()) {
    msg_error("mass files (filename=) are not supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (!meshgeo::bind_mesh_mass(*this, topology, geometry_state)) return;
  const MassElement k = meshgeo::checked_mass_element(*this, *topology, *geometry_state);
  if (k == MassElement::none) return;
  kind_ = static_cast<int>(k);
  follow_.owner = this;
  follow_.attach(topology.get());
  if (!meshgeo::mass_elements_in_states(*this, *topology, k, s.size(), geometry_state->size())) return;

  // A short vertexMass list is padded with its last value.
  {
    const auto& vm = vertex_mass.value();
    if (!vm.empty() && vm.size() < s.size()) {
      msg_warning("vertexMass has " + std::to_string(vm.size()) + " values for " + std::to_string(s.size()) +
                  " points: the missing ones take the last value");
      std::vector<double> p = vm;
      const double last = p.back();
      p.resize(s.size(), last);
      vertex_mass.set(std::move(p));
    }
  }

  auto init_from_total = [&] {
    meshgeo::reset_negative_total_mass(*this, total_mass);
    const double total = total_mass.value();
    const double sum = compute_vertex_mass(1.0);
    const double rho = sum < std::numeric_limits<double>::epsilon() ? 1.0 : total / sum;
    mass_density.set(rho);
    std::vector<double>& m = vertex_mass.edit();
    for (double& v : m) v *= rho;
  };

  const bool vm_set = vertex_mass.is_set(), md_set = mass_density.is_set(), tm_set = total_mass.is_set();
  if (tm_set) {
    if (vm_set || md_set) msg_warning("totalMass value overriding other mass information (vertexMass or massDensity)");
    init_from_total();
  } else if (md_set) {
    if (vm_set) msg_warning("massDensity value overriding the value of the attribute vertexMass");
    if (mass_density.value() < 0) {
      msg_warning("negative massDensity: the totalMass path is used");
      init_from_total();
    } else {
      total_mass.set(compute_vertex_mass(mass_density.value()));
    }
  } else if (vm_set) {
    const std::vector<double> vm = vertex_mass.value();
    if (!meshgeo::one_nonnegative_mass_per_point(vm, s.size())) {
      msg_warning("vertexMass must have one non-negative value per point: the totalMass path is used");
      init_from_total();
    } else {
      double sum_in = 0;
      for (double v : vm) sum_in += v;
      total_mass.set(sum_in);
      const double sum = compute_vertex_mass(1.0);
      mass_density.set(sum < std::numeric_limits<double>::epsilon() ? 1.0 : sum_in / sum);
      vertex_mass.set(vm);
    }
  } else {
    init_from_total();
  }
}

void DiagonalMass::on_topology_change(const MeshTopologyBase& t, const TopologyChange& c) {
  using T = TopologyChangeType;
  if (c.type == T::points_removed) {
    remove_swap_last(vertex_mass.edit(), c.indices);
    return;
  }
  if (c.type == T::points_added) {  // SOFA's applyPointCreation: a new point has no mass yet
    std::vector<double>& m = vertex_mass.edit();
    m.resize(m.size() + c.indices.size(), 0.0);
    return;
  }
  const MassElement k = static_cast<MassElement>(kind_);
  // Additions (SOFA's apply*Creation; propagated after the container changed): each new
  // element gives ρ·measure/nv to each of its vertices, and nv times that to the total.
  const bool added = (c.type == T::edges_added && k == MassElement::edge) ||
                     (c.type == T::triangles_added && k == MassElement::triangle) ||
                     (c.type == T::tetrahedra_added && k == MassElement::tetra) ||
                     (c.type == T::quads_added && k == MassElement::quad) ||
                     (c.type == T::hexahedra_added && k == MassElement::hexa);
  const bool mine = added || (c.type == T::edges_removed && k == MassElement::edge) ||
                    (c.type == T::triangles_removed && k == MassElement::triangle) ||
                    (c.type == T::tetrahedra_removed && k == MassElement::tetra) ||
                    (c.type == T::quads_removed && k == MassElement::quad) ||
                    (c.type == T::hexahedra_removed && k == MassElement::hexa);
  if (!mine) return;
  // Removals arrive before the container changes: the removed elements can still be read.
  const MechanicalState& g = *geometry_state;
  const std::vector<double>& X = g.read(kRestPosition);
  const int w = g.info().coord_width;
  const double rho = mass_density.value();
  std::vector<double>& m = vertex_mass.edit();
  double total = total_mass.value();
  auto take = [&](const auto& e, double share) {
    if (added) {
      for (unsigned v : e)
        if (v < m.size()) m[v] += share;
      total += static_cast<double>(e.size()) * share;
      return;
    }
    for (unsigned v : e)
      if (v < m.size()) m[v] -= share;
    total -= static_cast<double>(e.size()) * share;
  };
  for (unsigned i : c.indices) {
    if (k == MassElement::tetra && i < t.tetrahedra().size()) {
      const Tetra& e = t.tetrahedra()[i];
      take(e, (rho * meshgeo::tetra_volume(X, e[0], e[1], e[2], e[3])) / 4.0);
    } else if (k == MassElement::triangle && i < t.triangles().size()) {
      const Triangle& e = t.triangles()[i];
      take(e, (rho * meshgeo::triangle_area(X, w, e[0], e[1], e[2])) / 3.0);
    } else if (k == MassElement::hexa && i < t.hexahedra().size()) {
      const Hexa& e = t.hexahedra()[i];
      take(e, (rho * meshgeo::hexa_volume(X, e)) / 8.0);
    } else if (k == MassElement::quad && i < t.quads().size()) {
      const Quad& e = t.quads()[i];
      take(e, (rho * meshgeo::quad_area(X, w, e)) / 4.0);
    } else if (k == MassElement::edge && i < t.edges().size()) {
      const Edge& e = t.edges()[i];
      take(e, (rho * meshgeo::edge_length(X, w, e[0], e[1])) / 2.0);
    }
  }
  total_mass.set(total);
}

void DiagonalMass::add_force(const MechParams& p) {
  if (separate_gravity.value()) return;
  MechanicalState& s = *mstate;
  std::vector<double>& f = s.write(p.f);
  const Vec3 g = node()->gravity.value();
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < w; ++c) f[i * w + c] += g[c] * m[i];
}

std::optional<double> DiagonalMass::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const Vec3 g = node()->gravity.value();
  const int w = mstate->info().coord_width;
  const auto& m = vertex_mass.value();
  double e = 0;
  for (std::size_t i = 0; i < m.size() && (i + 1) * w <= x.size(); ++i)
    for (int c = 0; c < w; ++c) e -= g[c] * x[i * w + c] * m[i];
  return e;
}

void DiagonalMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  MechanicalState& s = *mstate;
  std::vector<double>& r = s.write(res);
  const std::vector<double>& d = s.read(dx);
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  const std::size_t n = std::min(m.size(), s.size());
  if (factor == 1.0) {
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < w; ++c) r[i * w + c] += d[i * w + c] * m[i];
  } else {
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < w; ++c) r[i * w + c] += (d[i * w + c] * m[i]) * factor;
  }
}

void DiagonalMass::acc_from_f(const MechParams&, int a, int f) {
  MechanicalState& s = *mstate;
  std::vector<double>& av = s.write(a);
  const std::vector<double>& fv = s.read(f);
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < w; ++c) av[i * w + c] = fv[i * w + c] / m[i];
}

void DiagonalMass::add_gravity_to_v(int v, double dt) {
  meshgeo::add_gravity_velocity(*mstate, v, node()->gravity.value(), dt);
}

bool DiagonalMass::build_mass(MatrixSink& M) {
  MechanicalState* s = mstate.get();
  const int w = s->info().deriv_width;
  const auto& m = vertex_mass.value();
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < w; ++c) M.add(s, i * w + c, s, i * w + c, m[i]);
  return true;
}

void register_diagonal_mass(Registry& r) {
  ComponentInfo info;
  info.name = "DiagonalMass";
  info.category = "Mass";
  info.description = "lumped mass per vertex from the element lengths, areas or volumes of the topology";
  // SOFA registers DiagonalMass<DataTypes, GeometricalTypes> (the geometry type defaults to the
  // state's): "Vec3d,Vec3d", "Vec2d,Vec2d", "Vec2d,Vec3d", "Vec1d,Vec1d", "Vec1d,Vec2d",
  // "Vec1d,Vec3d", "Rigid3d,Rigid3d" (Rigid2d is not used by SOFA's examples and not
  // supported here). The one-parameter names are the same classes; the geometry comes from
  // `geometryState` or the topology's state either way. Rigid frames are another class: their
  // masses are given, not computed from the topology.
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec1d,Vec1d", "Vec1d,Vec2d", "Vec1d,Vec3d",
                    "Vec2d,Vec2d", "Vec2d,Vec3d", "Vec3d,Vec3d", "Rigid3d", "Rigid3d,Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t.rfind("Rigid3d", 0) == 0) return std::make_unique<DiagonalRigidMass>();
    return std::make_unique<DiagonalMass>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
