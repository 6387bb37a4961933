#include "forcefield/fem/nonuniform/nonuniform_hexahedron_fem_force_field_and_mass.h"

#include <cmath>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "state/mechanical_object.h"
#include "topology/grid/sparse_grid_topology.h"

namespace sinew {

namespace fem {

float hexa_octant_weight(int c, int k, int j) {
  // Corners in SOFA's node order (kHexaCorner); octants are numbered x + 2y + 4z instead.
  const int oct[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
  float w = 1.0f;
  for (int a = 0; a < 3; ++a) {
    // Fine corner k of octant c sits at (oct + corner k) / 2 in the coarse cell; the trilinear
    // weight of coarse corner j along this axis is 1 − |that − corner j|: 1, ½ or 0.
    const int twice = oct[a] + kHexaCorner[k][a];  // twice the coordinate: 0, 1 or 2
    const int d = std::abs(twice - 2 * kHexaCorner[j][a]);
    w *= d == 0 ? 1.0f : (d == 1 ? 0.5f : 0.0f);
  }
  return w;
}

namespace {
// T[k][j] = weight of coarse corner j at fine corner k of `octant`, as SOFA rounds it (float).
void octant_weights(int octant, double T[8][8]) {
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j) T[k][j] = static_cast<double>(hexa_octant_weight(octant, k, j));
}
}  // namespace

void hexa_fine_to_coarse(Mat24& coarse, const Mat24& fine, int octant) {
  double T[8][8];
  octant_weights(octant, T);
  // SOFA's addFineToCoarse: A = fine·T, then coarse += Tᵀ·A, every sum in increasing k. T couples
  // a dof only with dofs of the same component; SOFA adds an exact 0 for the other pairs, which
  // are skipped here.
  Mat24 A;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      const int c = j % 3, nj = j / 3;
      double a = c == 0 ? fine(i, 0) * T[0][nj] : 0.0;
      for (int k = c == 0 ? 3 : c; k < 24; k += 3) a += fine(i, k) * T[k / 3][nj];
      A(i, j) = a;
    }
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      double s = coarse(i, j);
      for (int k = i % 3; k < 24; k += 3) s += T[k / 3][i / 3] * A(k, j);
      coarse(i, j) = s;
    }
}

void hexa_fine_to_coarse(std::array<double, 64>& coarse, const std::array<double, 64>& fine, int octant) {
  double T[8][8];
  octant_weights(octant, T);
  // The 24×24 form restricted to one component: the mass couples no two components, so each
  // nonzero entry goes through the same operations as in SOFA's full product.
  double A[8][8];
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      double a = fine[8 * i] * T[0][j];
      for (int k = 1; k < 8; ++k) a += fine[8 * i + k] * T[k][j];
      A[i][j] = a;
    }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      double s = coarse[8 * i + j];
      for (int k = 0; k < 8; ++k) s += T[k][i] * A[k][j];
      coarse[8 * i + j] = s;
    }
}

}  // namespace fem

namespace {

using Mass8 = std::array<double, 64>;

// The condensation of one cell, level by level down to the finest level used.
struct Condenser {
  const SparseGridTopology* grid;
  int finest;  // level whose cells get the classical matrices
  std::function<bool(std::array<Vec3, 8>, double, fem::Mat24&, Mass8&)> classical_matrices;
  std::vector<std::string>* problems;

  // Classical stiffness and mass of cell h of level k, both scaled by its stiffness coefficient.
  void classical(int k, std::size_t h, fem::Mat24& K, Mass8& M) const {
    const SparseGridTopology::LevelView L = grid->level(k);
    std::array<Vec3, 8> nodes;
    for (int w = 0; w < 8; ++w) nodes[w] = L.points[L.hexas[h][w]];
    if (!classical_matrices(nodes, static_cast<double>(L.stiffness[h]), K, M) && problems->size() < 10)
      problems->push_back("cell " + std::to_string(h) + " of virtual level " + std::to_string(k) +
                          " has a singular Jacobian");
  }

  // K and M of cell h of level k: classical at the finest level, else the sum of its octants'
  // matrices carried up (K and M must be zero on entry).
  void condense(int k, std::size_t h, fem::Mat24& K, Mass8& M) const {
    if (k == finest) {
      classical(k, h, K, M);
      return;
    }
    const std::array<int, 8>& children = grid->level(k).children[h];
    for (int c = 0; c < 8; ++c) {
      if (children[c] < 0) continue;
      fem::Mat24 Kf = fem::Mat24::Zero();
      Mass8 Mf{};
      condense(k + 1, static_cast<std::size_t>(children[c]), Kf, Mf);
      fem::hexa_fine_to_coarse(K, Kf, c);
      fem::hexa_fine_to_coarse(M, Mf, c);
    }
  }
};

}  // namespace

bool NonUniformHexahedronFEMForceFieldAndMass::classical_matrices(std::array<Vec3, 8> nodes, double coef,
                                                                  fem::Mat24& K, std::array<double, 64>& M) const {
  const auto* mo = dynamic_cast<const MechanicalObject*>(mstate.get());
  const Vec3 scale = mo ? mo->scale3d.value() : Vec3::Ones();  // SOFA scales the grid's points by it
  for (Vec3& p : nodes) p = p.cwiseProduct(scale);
  // SOFA condenses with the first element's material for every cell.
  const fem::HexaJacobianInfo info = fem::hexa_element_stiffness(nodes, fem_.material[0], coef, K);
  const double vol = (nodes[1] - nodes[0]).norm() * (nodes[3] - nodes[0]).norm() * (nodes[4] - nodes[0]).norm();
  M.fill((vol * hexa_mass_integral(density.value())) * coef);
  return !info.singular;
}

bool NonUniformHexahedronFEMForceFieldAndMass::compute_element_matrices(const SparseGridTopology& grid, int levels) {
  if (levels == 0) {
    msg_warning("nbVirtualFinerLevels is 0: the grid's cells get the classical (uniform) matrices");
  } else if (grid.kept_levels() < levels) {
    msg_warning("the sparse grid " + grid.describe() + " has " + std::to_string(grid.kept_levels()) +
                " virtual finer levels, fewer than nbVirtualFinerLevels = " + std::to_string(levels) +
                ": the grid's cells get the classical (uniform) matrices");
    levels = 0;
  }
  std::vector<std::string> problems;
  const Condenser cond{&grid, levels,
                       [this](std::array<Vec3, 8> n, double c, fem::Mat24& K, Mass8& M) {
                         return classical_matrices(n, c, K, M);
                       },
                       &problems};
  const std::size_t ne = fem_.size();
  nodal_mass_.assign(ne, Mass8{});
  for (std::size_t e = 0; e < ne; ++e) {
    fem::Mat24 K = fem::Mat24::Zero();
    cond.condense(0, e, K, nodal_mass_[e]);
    // The kernel reads its stiffness column by column (row c of the storage as column c: exact
    // for the classical K, symmetric to the bit). The condensed K is symmetric only to
    // round-off, so its transpose is stored: the products are then SOFA's K·x, each row
    // summed in SOFA's order.
    fem_.K[e] = K.transpose();
  }
  for (const std::string& p : problems) msg_warning(p);
  return true;
}

void NonUniformHexahedronFEMForceFieldAndMass::init() {
  // The uniform masses, gravity's particle masses (SOFA's rule is the same here) and the
  // stiffnesses of the grid's cells come first; the condensation replaces the matrices.
  HexahedronFEMForceFieldAndMass::init();
  if (state() != ComponentState::valid) return;
  const auto* grid = dynamic_cast<const SparseGridTopology*>(topology.get());
  if (!grid) {
    msg_error("the topology " + topology->describe() +
              " is not a sparse grid: the element matrices are condensed from a SparseGridTopology's virtual levels");
    set_state(ComponentState::invalid);
    return;
  }
  if (method.value() == "small") {
    // SOFA leaves the method unset (an uninitialised value) for anything but large and polar.
    msg_error("method small is not supported: use large or polar");
    set_state(ComponentState::invalid);
    return;
  }
  if (update_stiffness_matrix.value()) {
    // SOFA would recompute each element from the current nodes with a material it never filled
    // in here: no stiffness at all.
    msg_error("updateStiffnessMatrix is not supported: the condensed stiffness cannot be recomputed from the "
              "current positions");
    set_state(ComponentState::invalid);
    return;
  }
  const int levels = nb_virtual_finer_levels.value();
  if (levels < 0) {
    msg_error("nbVirtualFinerLevels must be >= 0 (got " + std::to_string(levels) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const std::size_t ne = fem_.size(), np = rest_.size();
  if (grid->level(0).hexas.size() != ne) {
    msg_error("the sparse grid changed since its hexahedra were read");
    set_state(ComponentState::invalid);
    return;
  }
  if (!compute_element_matrices(*grid, levels)) {
    set_state(ComponentState::invalid);
    return;
  }
  fem_.touch_stiffness();

  if (!use_mass.value()) {
    // SOFA's rule, kept: every point weighs totalMass divided by the number of elements.
    particle_mass_.assign(np, total_mass.value() / static_cast<double>(ne));
    lumped_.clear();
  } else if (lumped_mass.value()) {
    lumped_.assign(np, Vec3::Zero());
    for (std::size_t e = 0; e < ne; ++e)
      for (int w = 0; w < 8; ++w)
        for (int j = 0; j < 8; ++j)
          for (int c = 0; c < 3; ++c)
            lumped_[fem_.hexa[e][w]][c] +=
                component_mass_.empty() ? nodal_mass_[e][8 * w + j] : component_mass_[e][c][8 * w + j];
    for (Vec3& l : lumped_) l = l.cwiseAbs();  // SOFA flips negative row sums
  }
}

void NonUniformHexahedronFEMForceFieldAndMass::add_mdx(const MechParams& p, int res, int dx, double factor) {
  if (use_mass.value()) {
    HexahedronFEMForceFieldAndMass::add_mdx(p, res, dx, factor);
    return;
  }
  auto f = as_vec3(mstate->write(res));
  const auto d = as_vec3(mstate->read(dx));
  for (std::size_t i = 0; i < particle_mass_.size(); ++i) f[i] += d[i] * particle_mass_[i] * factor;
}

void register_nonuniform_hexahedron_fem_force_field_and_mass(Registry& r) {
  ComponentInfo info;
  info.name = "NonUniformHexahedronFEMForceFieldAndMass";
  info.category = "ForceField/FEM";
  info.description =
      "hexahedral finite elements and mass on a sparse grid, condensed from its virtual finer levels";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<NonUniformHexahedronFEMForceFieldAndMass>();
  r.add(std::move(info));
}

}  // namespace sinew
