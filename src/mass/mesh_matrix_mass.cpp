#include "mass/mesh_matrix_mass.h"

#include <limits>
#include <map>

#include "core/node.h"
#include "core/registry.h"
#include "mass/mesh_geometry.h"

namespace sinew {

using meshgeo::MassElement;

namespace {
// Local edges of each element kind (SOFA's edgesIn* arrays; the order within an
// element does not change the sums).
constexpr int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kHexEdges[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                  {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
}  // namespace

double MeshMatrixMass::compute_mass(const std::vector<double>& rho) {
  MechanicalState& s = *mstate;
  MechanicalState& g = *geometry_state;
  const std::vector<double>& X = g.read(compute_mass_on_rest.get() ? kRestPosition : kPosition);
  const int w = g.info().coord_width;
  const MeshTopologyBase& t = *topology;
  std::vector<double> vm(s.size(), 0.0), em(edges_.size(), 0.0);
  double total = 0;

  // One pass per element kind: measure, vertex divisor, edge divisor, counts.
  auto run = [&](std::size_t n, auto measure, auto node_of, int nv, int ne, double vdiv, double ediv) {
    if (!lumped_) {
      for (std::size_t e = 0; e < n; ++e) {
        const double mass = (rho[e] * measure(e)) / ediv;
        for (int j = 0; j < ne; ++j) em[elem_edges_[e][j]] += mass;
        total += static_cast<double>(ne) * mass * 2.0;
      }
    }
    for (std::size_t e = 0; e < n; ++e) {
      const double mass = (rho[e] * measure(e)) / vdiv;
      for (int j = 0; j < nv; ++j) vm[node_of(e, j)] += mass;
      if (!lumped_) total += static_cast<double>(nv) * mass;
      else total += static_cast<double>(nv) * mass * coef_;
    }
  };

  switch (static_cast<MassElement>(kind_)) {
    case MassElement::triangle: {
      const auto& el = t.triangles();
      run(el.size(), [&](std::size_t e) { return meshgeo::triangle_area(X, w, el[e][0], el[e][1], el[e][2]); },
          [&](std::size_t e, int j) { return el[e][j]; }, 3, 3, 6.0, 12.0);
      break;
    }
    case MassElement::quad: {
      const auto& el = t.quads();
      run(el.size(), [&](std::size_t e) { return meshgeo::quad_area(X, w, el[e]); },
          [&](std::size_t e, int j) { return el[e][j]; }, 4, 4, 8.0, 16.0);
      break;
    }
    case MassElement::tetra: {
      const auto& el = t.tetrahedra();
      run(el.size(), [&](std::size_t e) { return meshgeo::tetra_volume(X, el[e][0], el[e][1], el[e][2], el[e][3]); },
          [&](std::size_t e, int j) { return el[e][j]; }, 4, 6, 10.0, 20.0);
      break;
    }
    case MassElement::hexa: {
      const auto& el = t.hexahedra();
      run(el.size(), [&](std::size_t e) { return meshgeo::hexa_volume(X, el[e]); },
          [&](std::size_t e, int j) { return el[e][j]; }, 8, 12, 20.0, 40.0);
      break;
    }
    default:
      break;  // edges only: SOFA computes no mass
  }
  vertex_mass.set(std::move(vm));
  edge_mass.set(std::move(em));
  return total;
}

void MeshMatrixMass::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  if (!meshgeo::bind_mesh_mass(*this, topology, geometry_state)) return;
  const MeshTopologyBase& t = *topology;
  const MassElement k = meshgeo::checked_mass_element(*this, t, *geometry_state);
  if (k == MassElement::none) return;
  if (k == MassElement::edge) msg_warning("edge topologies get no mass (as in SOFA)");
  kind_ = static_cast<int>(k);
  lumped_ = lumping.get();
  if (!meshgeo::mass_elements_in_states(*this, t, k, s.size(), geometry_state->size())) return;

  // Edge list and edges of each element.
  edges_ = t.edges();
  for (const Edge& e : edges_)
    if (e[0] >= s.size() || e[1] >= s.size()) {
      msg_error("an edge of " + t.describe() + " uses a point out of range");
      set_state(ComponentState::invalid);
      return;
    }
  switch (k) {
    case MassElement::triangle: coef_ = 2.0; n_elements_ = t.triangles().size(); break;
    case MassElement::quad: coef_ = 2.0; n_elements_ = t.quads().size(); break;
    case MassElement::tetra: coef_ = 2.5; n_elements_ = t.tetrahedra().size(); break;
    case MassElement::hexa: coef_ = 2.5; n_elements_ = t.hexahedra().size(); break;
    default: coef_ = 0.0; n_elements_ = 0; break;
  }
  elem_edges_.assign(n_elements_, {});
  if (!lumped_ && n_elements_ > 0) {
    std::map<std::pair<unsigned, unsigned>, unsigned> index;
    for (std::size_t i = 0; i < edges_.size(); ++i) {
      const Edge& e = edges_[i];
      index.emplace(std::make_pair(std::min(e[0], e[1]), std::max(e[0], e[1])), static_cast<unsigned>(i));
    }
    auto fill = [&](std::size_t e, const auto& elem, const auto& local, int n) -> bool {
      for (int j = 0; j < n; ++j) {
        const unsigned a = elem[local[j][0]], b = elem[local[j][1]];
        auto it = index.find({std::min(a, b), std::max(a, b)});
        if (it == index.end()) {
          msg_error("element " + std::to_string(e) + ": its edge (" + std::to_string(a) + ", " + std::to_string(b) +
                    ") is missing from the edges of " + t.describe());
          return false;
        }
        elem_edges_[e][j] = it->second;
      }
      return true;
    };
    bool ok = true;
    for (std::size_t e = 0; ok && e < n_elements_; ++e) {
      switch (k) {
        case MassElement::triangle: ok = fill(e, t.triangles()[e], kTriEdges, 3); break;
        case MassElement::quad: ok = fill(e, t.quads()[e], kQuadEdges, 4); break;
        case MassElement::tetra: ok = fill(e, t.tetrahedra()[e], kTetEdges, 6); break;
        case MassElement::hexa: ok = fill(e, t.hexahedra()[e], kHexEdges, 12); break;
        default: break;
      }
    }
    if (!ok) {
      set_state(ComponentState::invalid);
      return;
    }
  }

  auto init_from_total = [&] {
    meshgeo::reset_negative_total_mass(*this, total_mass);
    const double total_in = total_mass.value();
    const double sum = compute_mass(std::vector<double>(n_elements_, 1.0));
    const double md = sum > std::numeric_limits<double>::epsilon() ? total_in / sum : 1.0;
    mass_density.set(std::vector<double>(n_elements_, md));
    total_mass.set(total_in);
    for (double& v : vertex_mass.edit()) v *= md;
    for (double& v : edge_mass.edit()) v *= md;
  };
  // Per-element densities from massDensity (1 value or one per element); false when unusable.
  auto densities = [&](std::vector<double>& rho) -> bool {
    const auto& md = mass_density.value();
    if (md.size() == 1) {
      if (md[0] < 0) return false;
      rho.assign(n_elements_, md[0]);
      return true;
    }
    if (md.size() != n_elements_) {
      msg_warning("massDensity has " + std::to_string(md.size()) + " values, expected 1 or " +
                  std::to_string(n_elements_));
      return false;
    }
    for (double v : md)
      if (v < 0) return false;
    rho = md;
    return true;
  };

  const bool vm_set = vertex_mass.is_set(), md_set = mass_density.is_set(), tm_set = total_mass.is_set();
  const bool em_set = edge_mass.is_set();
  if (tm_set) {
    if (vm_set || md_set) msg_warning("totalMass value overriding other mass information (vertexMass or massDensity)");
    init_from_total();
  } else if (md_set) {
    if (vm_set) msg_warning("massDensity value overriding the value of the attribute vertexMass");
    std::vector<double> rho;
    if (!densities(rho)) {
      init_from_total();
    } else {
      mass_density.set(rho);
      compute_mass(rho);
      double sum = 0;
      for (double v : vertex_mass.value()) sum += v;
      if (!lumped_) {
        double se = 0;
        for (double v : edge_mass.value()) se += v;
        sum += se * 2.0;
      } else {
        sum *= coef_;
      }
      total_mass.set(sum);
    }
  } else if (vm_set) {
    const std::vector<double> vm = vertex_mass.value();
    const bool ok = meshgeo::one_nonnegative_mass_per_point(vm, s.size());
    if (em_set && !lumped_) {
      const std::vector<double> em = edge_mass.value();
      bool eok = em.size() == edges_.size();
      for (double v : em)
        if (v < 0) eok = false;
      if (!ok || !eok) {
        msg_warning("vertexMass/edgeMass do not match the topology: the totalMass path is used");
        init_from_total();
      } else {
        double sum = 0;
        for (double v : vm) sum += v;
        double se = 0;
        for (double v : em) se += v;
        total_mass.set(sum + se * 2.0);
      }
    } else if (lumped_) {
      if (!ok) {
        msg_warning("vertexMass must have one non-negative value per point: the totalMass path is used");
        init_from_total();
      } else {
        double sum = 0;
        for (double v : vm) sum += v;
        total_mass.set(sum * coef_);
        edge_mass.set(std::vector<double>(edges_.size(), 0.0));
      }
    } else {
      msg_error("initialization using vertexMass requires the lumping option or the edgeMass information");
      init_from_total();
    }
  } else {
    init_from_total();
  }
}

void MeshMatrixMass::add_force(const MechParams& p) {
  if (separate_gravity.value()) return;
  MechanicalState& s = *mstate;
  std::vector<double>& f = s.write(p.f);
  const Vec3 g = node()->gravity.value();
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  const std::size_t n = std::min(m.size(), s.size());
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < w; ++c) f[i * w + c] += g[c] * m[i] * coef_;
}

void MeshMatrixMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  MechanicalState& s = *mstate;
  std::vector<double>& r = s.write(res);
  const std::vector<double>& d = s.read(dx);
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  const std::size_t n = std::min(m.size(), s.size());
  if (lumped_) {
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < w; ++c) r[i * w + c] += d[i * w + c] * m[i] * coef_ * factor;
    return;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < w; ++c) r[i * w + c] += d[i * w + c] * m[i] * factor;
  const auto& em = edge_mass.value();
  for (std::size_t j = 0; j < edges_.size(); ++j) {
    const unsigned a = edges_[j][0], b = edges_[j][1];
    const double tm = em[j] * factor;
    for (int c = 0; c < w; ++c) r[a * w + c] += d[b * w + c] * tm;
    for (int c = 0; c < w; ++c) r[b * w + c] += d[a * w + c] * tm;
  }
}

void MeshMatrixMass::acc_from_f(const MechParams&, int a, int f) {
  if (!lumped_) {
    msg_error("accFromF can't be used with a non-lumped MeshMatrixMass (set lumping=true or use a DiagonalMass)");
    return;
  }
  MechanicalState& s = *mstate;
  std::vector<double>& av = s.write(a);
  const std::vector<double>& fv = s.read(f);
  const int w = s.info().deriv_width;
  const auto& m = vertex_mass.value();
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < w; ++c) av[i * w + c] = fv[i * w + c] / (m[i] * coef_);
}

void MeshMatrixMass::add_gravity_to_v(int v, double dt) {
  meshgeo::add_gravity_velocity(*mstate, v, node()->gravity.value(), dt);
}

bool MeshMatrixMass::build_mass(MatrixSink& M) {
  MechanicalState* s = mstate.get();
  const int w = s->info().deriv_width;
  const auto& m = vertex_mass.value();
  if (lumped_) {
    for (std::size_t i = 0; i < m.size(); ++i)
      for (int c = 0; c < w; ++c) M.add(s, i * w + c, s, i * w + c, m[i] * coef_);
    return true;
  }
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < w; ++c) M.add(s, i * w + c, s, i * w + c, m[i]);
  const auto& em = edge_mass.value();
  for (std::size_t j = 0; j < edges_.size(); ++j) {
    const unsigned a = edges_[j][0], b = edges_[j][1];
    for (int c = 0; c < w; ++c) {
      M.add(s, a * w + c, s, b * w + c, em[j]);
      M.add(s, b * w + c, s, a * w + c, em[j]);
    }
  }
  return true;
}

void register_mesh_matrix_mass(Registry& r) {
  ComponentInfo info;
  info.name = "MeshMatrixMass";
  info.category = "Mass";
  info.description = "consistent (or lumped) mass matrix from the element lengths, areas or volumes of the topology";
  // SOFA's MeshMatrixMass<DataTypes, GeometricalTypes>: Vec3, Vec2, Vec2-Vec3, Vec1, Vec1-Vec2,
  // Vec1-Vec3 (the one-parameter names are <T, T>). The geometry comes from `geometryState` or
  // the topology's state either way (its own width).
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec1d,Vec1d", "Vec1d,Vec2d", "Vec1d,Vec3d",
                    "Vec2d,Vec2d", "Vec2d,Vec3d", "Vec3d,Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<MeshMatrixMass>();
  r.add(std::move(info));
}

}  // namespace sinew
