#include "mass/fem_mass.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/finite_element.h"
#include "topology/mesh_topology.h"

namespace sinew {

namespace {

// SOFA's quadrature of ∫ρ N_i N_j over one element (FEMMass.inl).
template <class E>
bool element_mass(const std::array<Vec3, E::kNodes>& X, const std::array<double, E::kNodes>& rho, double* M) {
  constexpr int N = E::kNodes;
  for (int i = 0; i < N * N; ++i) M[i] = 0.0;
  Vec3 Xa[N];
  for (int k = 0; k < N; ++k) Xa[k] = X[k];
  const auto points = E::points();
  const auto weights = E::weights();
  for (int q = 0; q < E::kPoints; ++q) {
    double g[N][3];
    E::gradient(points[q], g);
    const fe::Mat3d J = fe::jacobian<N>(Xa, g);
    const double detJ = std::abs(fe::determinant(J));
    if (!(detJ > 0) || !std::isfinite(detJ)) return false;
    double Nq[N];
    E::shape(points[q], Nq);
    double density = 0.0;  // std::inner_product from 0
    for (int k = 0; k < N; ++k) density += rho[k] * Nq[k];
    const double s = weights[q] * density * detJ;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) M[i * N + j] += (Nq[i] * Nq[j]) * s;
  }
  return true;
}

}  // namespace

bool FEMMass::tetra_mass(const std::array<Vec3, 4>& X, const std::array<double, 4>& rho, double* M) {
  return element_mass<fe::Tetra4>(X, rho, M);
}
bool FEMMass::hexa_mass(const std::array<Vec3, 8>& X, const std::array<double, 8>& rho, double* M) {
  return element_mass<fe::Hexa8>(X, rho, M);
}
bool FEMMass::prism_mass(const std::array<Vec3, 6>& X, const std::array<double, 6>& rho, double* M) {
  return element_mass<fe::Prism6>(X, rho, M);
}
bool FEMMass::pyramid_mass(const std::array<Vec3, 5>& X, const std::array<double, 5>& rho, double* M) {
  return element_mass<fe::Pyramid5>(X, rho, M);
}

void FEMMass::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  auto fail = [&](const std::string& m) {
    msg_error(m);
    set_state(ComponentState::invalid);
  };
  if (!require_vec3_state(*this) || !bind_node_topology(*this, topology, "link one with topology=\"@...\"")) return;
  MechanicalState& s = *mstate;
  if (!nodal_mass_density) nodal_mass_density.set(node()->find_up<NodalMassDensity>());
  if (!nodal_mass_density)
    return fail("No nodal mass density component found (add a NodalMassDensity or link nodalMassDensity=\"@...\")");

  const std::size_t n = s.size();
  const std::span<const Vec3> X0 = as_vec3(s.read(kRestPosition));
  const NodalMassDensity& rho = *nodal_mass_density;

  struct Triplet {
    unsigned r, c;
    double v;
  };
  std::vector<Triplet> trip;
  auto assemble = [&](const auto& elems, auto mass_fn, auto tag) -> bool {
    constexpr int NN = decltype(tag)::value;
    trip.reserve(elems.size() * NN * NN);
    for (std::size_t e = 0; e < elems.size(); ++e) {
      std::array<Vec3, NN> X;
      std::array<double, NN> r;
      for (int k = 0; k < NN; ++k) {
        const unsigned id = elems[e][k];
        if (id >= n) {
          fail("element " + std::to_string(e) + ": node index " + std::to_string(id) +
               " is out of range (the state has " + std::to_string(n) + " points)");
          return false;
        }
        X[k] = X0[id];
        r[k] = rho.node_property(id);
      }
      double M[NN * NN];
      if (!mass_fn(X, r, M)) {
        fail("element " + std::to_string(e) + ": degenerate element (zero Jacobian determinant at rest)");
        return false;
      }
      for (int i = 0; i < NN; ++i)
        for (int j = 0; j < NN; ++j) trip.push_back({elems[e][i], elems[e][j], M[i * NN + j]});
    }
    return true;
  };
  bool ok = false;
  const auto run = [&](const auto& elems, const char* name, auto mass_fn, auto tag) {
    if (elems.empty()) return fail("the topology " + topology->describe() + " has no " + name);
    ok = assemble(elems, mass_fn, tag);
  };
  switch (kind_) {
    case ElementKind::tetrahedron:
      run(topology->tetrahedra(), "tetrahedra", &FEMMass::tetra_mass, std::integral_constant<int, 4>{});
      break;
    case ElementKind::hexahedron:
      run(topology->hexahedra(), "hexahedra", &FEMMass::hexa_mass, std::integral_constant<int, 8>{});
      break;
    case ElementKind::prism:
      run(prisms_of(*topology), "prisms", &FEMMass::prism_mass, std::integral_constant<int, 6>{});
      break;
    case ElementKind::pyramid:
      run(pyramids_of(*topology), "pyramids", &FEMMass::pyramid_mass, std::integral_constant<int, 5>{});
      break;
  }
  if (!ok) return;

  // Compress as SOFA's CompressedRowSparseMatrix does: the (row, column, value)
  // list in insertion order is std::sort-ed on (row, column) only (not stable:
  // same algorithm, same comparisons, hence the same order of duplicates), then
  // duplicates are summed in that order.
  std::sort(trip.begin(), trip.end(),
            [](const Triplet& a, const Triplet& b) { return (a.r < b.r) || (a.r == b.r && a.c < b.c); });
  row_begin_.assign(n + 1, 0);
  cols_.clear();
  vals_.clear();
  std::size_t k = 0;
  for (unsigned row = 0; row < n; ++row) {
    row_begin_[row] = cols_.size();
    while (k < trip.size() && trip[k].r == row) {
      const unsigned c = trip[k].c;
      double v = trip[k].v;
      ++k;
      while (k < trip.size() && trip[k].r == row && trip[k].c == c) v += trip[k++].v;
      cols_.push_back(c);
      vals_.push_back(v);
    }
  }
  row_begin_[n] = cols_.size();
  total_ = 0;
  for (double v : vals_) total_ += v;
}

void FEMMass::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::span<Vec3> f = as_vec3(s.write(p.f));
  const Vec3 g = node()->gravity.value();
  const std::size_t n = row_begin_.size() - 1;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = row_begin_[r]; k < row_begin_[r + 1]; ++k) {
      const double m = vals_[k];
      f[r][0] += m * g[0];
      f[r][1] += m * g[1];
      f[r][2] += m * g[2];
    }
}

std::optional<double> FEMMass::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::span<const Vec3> x = as_vec3(mstate->read(kPosition));
  const Vec3 g = node()->gravity.value();
  double e = 0;
  for (std::size_t r = 0; r + 1 < row_begin_.size(); ++r)
    for (std::size_t k = row_begin_[r]; k < row_begin_[r + 1]; ++k) e -= x[r].dot(g * vals_[k]);
  return e;
}

void FEMMass::add_mdx(const MechParams&, int res, int dx, double factor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::span<Vec3> out = as_vec3(s.write(res));
  const std::span<const Vec3> d = as_vec3(s.read(dx));
  const std::size_t n = row_begin_.size() - 1;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = row_begin_[r]; k < row_begin_[r + 1]; ++k) {
      const double m = factor * vals_[k];
      const Vec3& v = d[cols_[k]];
      out[r][0] += m * v[0];
      out[r][1] += m * v[1];
      out[r][2] += m * v[2];
    }
}

void FEMMass::acc_from_f(const MechParams&, int, int) {
  if (!acc_warned_)
    msg_error("the method 'accFromF' can't be used with this component as this SPARSE mass matrix can't be "
              "inversed easily (use an implicit solver)");
  acc_warned_ = true;
}

void FEMMass::add_gravity_to_v(int v, double dt) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::span<Vec3> vv = as_vec3(s.write(v));
  const Vec3 dv = node()->gravity.value() * dt;
  for (Vec3& x : vv) x += dv;
}

bool FEMMass::build_mass(MatrixSink& M) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  const std::size_t n = row_begin_.size() - 1;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = row_begin_[r]; k < row_begin_[r + 1]; ++k)
      for (int d = 0; d < 3; ++d) M.add(s, 3 * r + d, s, 3 * cols_[k] + d, vals_[k]);
  return true;
}

void register_fem_mass(Registry& r) {
  ComponentInfo info;
  info.name = "FEMMass";
  info.category = "Mass";
  info.description = "Finite-element mass (inertia and body force)";
  info.templates = {"Vec3d,Tetrahedron", "Vec3d,Hexahedron", "Vec3d,Prism", "Vec3d,Pyramid"};
  info.default_template = "Vec3d,Tetrahedron";
  info.requirement = Requirement::none;  // the Vec3d state is checked at init
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    FEMMass::ElementKind kind = FEMMass::ElementKind::tetrahedron;
    if (tmpl.find("Hexahedron") != std::string::npos) kind = FEMMass::ElementKind::hexahedron;
    else if (tmpl.find("Prism") != std::string::npos) kind = FEMMass::ElementKind::prism;
    else if (tmpl.find("Pyramid") != std::string::npos) kind = FEMMass::ElementKind::pyramid;
    return std::make_unique<FEMMass>(kind);
  };
  r.add(std::move(info));
}

}  // namespace sinew
