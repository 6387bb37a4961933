#include "forcefield/fem/nonuniform/hexahedron_composite_fem_force_field_and_mass.h"

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <set>
#include <utility>

#include "core/node.h"
#include "core/registry.h"
#include "math/sofa_vec.h"
#include "topology/grid/sparse_grid_ramification_topology.h"

namespace sinew {

namespace {

using Mat = Eigen::MatrixXd;
using Weight = HexahedronCompositeFEMForceFieldAndMass::Weight;
using Mass8 = std::array<double, 64>;

// The 27 nodes of a cell split in 2×2×2 are numbered x + 3y + 9z (x, y, z in 0..2).
// Trilinear weight of corner j at node p: 1, ½, ¼, ⅛ or 0 (exact in binary).
double middle_weight(int p, int j) {
  const int x[3] = {p % 3, (p / 3) % 3, p / 9};
  double w = 1.0;
  for (int a = 0; a < 3; ++a) {
    const int d = std::abs(x[a] - 2 * kHexaCorner[j][a]);
    w *= d == 0 ? 1.0 : (d == 1 ? 0.5 : 0.0);
  }
  return w;
}

// Node (0..26) of corner j of octant o (x + 2y + 4z).
int octant_node(int o, int j) {
  return ((o & 1) + kHexaCorner[j][0]) + 3 * (((o >> 1) & 1) + kHexaCorner[j][1]) + 9 * (((o >> 2) & 1) + kHexaCorner[j][2]);
}

// The corner a node is (its coordinates all 0 or 2), else −1.
int coarse_corner(int p) {
  const int x[3] = {p % 3, (p / 3) % 3, p / 9};
  for (int j = 0; j < 8; ++j)
    if (x[0] == 2 * kHexaCorner[j][0] && x[1] == 2 * kHexaCorner[j][1] && x[2] == 2 * kHexaCorner[j][2]) return j;
  return -1;
}

// The stiffness SOFA gives an empty octant (its RIGID_STIFFNESS): the classical stiffness of a
// unit cube with E = 1.02e12 and ν = 0, each entry printed with 6 significant digits and
// stored in single precision.
fem::Mat24 rigid_stiffness() {
  std::array<Vec3, 8> cube;
  for (int j = 0; j < 8; ++j) cube[j] = Vec3(kHexaCorner[j][0], kHexaCorner[j][1], kHexaCorner[j][2]);
  fem::Mat24 K;
  fem::hexa_element_stiffness(cube, 1.02e12, 0.0, K);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", K(i, j));
      K(i, j) = static_cast<double>(static_cast<float>(std::strtod(text, nullptr)));
    }
  return K;
}

// SOFA's Mat product: each entry summed over k in increasing order.
Weight mat_mul(const Weight& a, const Weight& b) {
  Weight r;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) {
      double s = a(i, 0) * b(0, j);
      for (int k = 1; k < 24; ++k) s += a(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

// The nodal mass N ⊗ I3 as a 24×24 matrix (dof order node-major).
fem::Mat24 expand_mass(const Mass8& N) {
  fem::Mat24 M = fem::Mat24::Zero();
  for (int w = 0; w < 8; ++w)
    for (int j = 0; j < 8; ++j)
      for (int c = 0; c < 3; ++c) M(3 * w + c, 3 * j + c) = N[8 * w + j];
  return M;
}

// The homogenization of one coarse cell, level by level (SOFA's
// computeMechanicalMatricesRecursivelyWithRamifications), and the weights it leaves.
struct Homogenizer {
  using Classical = std::function<bool(const std::array<Vec3, 8>&, double, fem::Mat24&, Mass8&)>;
  Homogenizer(const SparseGridRamificationTopology& g, int l, bool c, Classical f)
      : grid(g), levels(l), complete(c), classical(std::move(f)) {}

  const SparseGridRamificationTopology& grid;
  int levels;         // the force field's nbVirtualFinerLevels
  bool complete;      // completeInterpolation
  Classical classical;
  fem::Mat24 rigid = rigid_stiffness();
  // weights[levels − k][h]: u of hexahedron h of level k (8 × 3) = W · u of its parent's corners.
  std::vector<std::vector<Weight>> weights;
  std::vector<HexahedronCompositeFEMForceFieldAndMass::FinalWeight>* final_weights = nullptr;
  int singular = 0;

  void condense(int k, unsigned h, fem::Mat24& K, fem::Mat24& M) {
    if (k == levels) {
      const auto L = grid.ramified_level(k);
      std::array<Vec3, 8> nodes;
      for (int w = 0; w < 8; ++w) nodes[w] = L.points[L.hexas[h][w]];
      Mass8 N;
      // The level's stiffness coefficient, for the mass too (SOFA's computeClassicalMechanicalMatrices).
      // A ramified finest level lists its coefficients per unramified cell but is read by
      // hexahedron (SOFA): the hexahedra past the list's end, which SOFA reads out of bounds, get 1.
      const double coef = h < L.stiffness.size() ? static_cast<double>(L.stiffness[h]) : 1.0;
      if (!classical(nodes, coef, K, N)) ++singular;
      M = expand_mass(N);
      return;
    }
    const auto C = grid.ramified_level(k), F = grid.ramified_level(k + 1);
    const std::array<std::vector<int>, 8>& kids = C.children[h];
    const Hexa& coarse = C.hexas[h];

    std::array<Vec3, 27> node_pos;
    for (int p = 0; p < 27; ++p) {
      Vec3 x = Vec3::Zero();
      for (int j = 0; j < 8; ++j) x += C.points[coarse[j]] * middle_weight(p, j);
      node_pos[p] = x;
    }

    // The finer cells (recursively), and the fine points found at each of the 27 nodes.
    std::array<std::vector<fem::Mat24>, 8> fineK, fineM;
    std::array<std::set<unsigned>, 27> at;
    for (int o = 0; o < 8; ++o) {
      fineK[o].resize(kids[o].size());
      fineM[o].resize(kids[o].size());
      for (std::size_t c = 0; c < kids[o].size(); ++c) {
        const auto kid = static_cast<unsigned>(kids[o][c]);
        condense(k + 1, kid, fineK[o][c], fineM[o][c]);
        const Hexa& fh = F.hexas[kid];
        for (int w = 0; w < 8; ++w)
          for (int p = 0; p < 27; ++p) {
            const Vec3 d = node_pos[p] - F.points[fh[w]];
            if (std::fabs(sofa_dot(d, d)) < 1.0e-5) {
              at[p].insert(fh[w]);
              break;
            }
          }
      }
    }
    // Nodes no fine cell reaches get labels of their own, counted down from the invalid index.
    unsigned fictive = ~0u;
    for (auto& s : at)
      if (s.empty()) s.insert(fictive--);

    // The cells to assemble: each octant's fine cells, or one fictive very stiff cube.
    struct Cell {
      std::array<unsigned, 8> nodes;
      int octant;
      int child;  // index in kids[octant]; −1: fictive
    };
    std::vector<Cell> cells;
    for (int o = 0; o < 8; ++o) {
      if (kids[o].empty()) {
        Cell c{{}, o, -1};
        for (int j = 0; j < 8; ++j) c.nodes[j] = *at[octant_node(o, j)].begin();
        cells.push_back(c);
        continue;
      }
      for (std::size_t c = 0; c < kids[o].size(); ++c) {
        Cell cell{{}, o, static_cast<int>(c)};
        const Hexa& fh = F.hexas[static_cast<unsigned>(kids[o][c])];
        for (int j = 0; j < 8; ++j) cell.nodes[j] = fh[j];
        cells.push_back(cell);
      }
    }
    std::map<unsigned, int> ass;  // fine point → assembly index, by node then label
    int n = 0;
    for (const auto& s : at)
      for (unsigned q : s) ass[q] = n++;

    Mat Kass = Mat::Zero(3 * n, 3 * n), Kstat = Mat::Zero(3 * n, 3 * n), Mass = Mat::Zero(3 * n, 3 * n);
    for (const Cell& cell : cells)
      for (int j = 0; j < 8; ++j) {
        const int v1 = ass[cell.nodes[j]];
        for (int l = 0; l < 8; ++l) {
          const int v2 = ass[cell.nodes[l]];
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
              if (cell.child < 0) {
                Kstat(3 * v1 + a, 3 * v2 + b) += rigid(3 * j + a, 3 * l + b);
                continue;
              }
              const fem::Mat24& fk = fineK[cell.octant][cell.child];
              Kass(3 * v1 + a, 3 * v2 + b) += fk(3 * j + a, 3 * l + b);
              Kstat(3 * v1 + a, 3 * v2 + b) += fk(3 * j + a, 3 * l + b);
              Mass(3 * v1 + a, 3 * v2 + b) += fineM[cell.octant][cell.child](3 * j + a, 3 * l + b);
            }
        }
      }

    // Held (coarse corner) and free points, numbered apart; the mask keeps, for each fine point,
    // the corners of its trilinear support (an edge point its edge's two, …), component by component.
    std::map<unsigned, int> cut, corner_of;
    std::array<std::vector<unsigned>, 8> at_corner;
    int ncut = 0, nheld = 0;
    Mat mask = Mat::Zero(3 * n, 24);
    for (int p = 0; p < 27; ++p) {
      const int cc = coarse_corner(p);
      for (unsigned q : at[p]) {
        const int l = ass[q];
        if (cc >= 0) {
          cut[q] = nheld++;
          corner_of[q] = cc;
          at_corner[cc].push_back(q);
          for (int a = 0; a < 3; ++a) mask(3 * l + a, 3 * cc + a) = 1;
        } else {
          cut[q] = ncut++;
          corner_of[q] = -1;
          for (int j = 0; j < 8; ++j)
            if (middle_weight(p, j) != 0)
              for (int a = 0; a < 3; ++a) mask(3 * l + a, 3 * j + a) = 1;
        }
      }
    }
    // [Kf −G]: the free points' columns, then −1 on each held point's own column.
    Mat Kg = Mat::Zero(3 * n, 3 * nheld), A = Mat::Zero(3 * n, 3 * n);
    for (const auto& [q, col] : cut) {
      const int src = ass[q];
      Mat& dst = corner_of[q] >= 0 ? Kg : A;
      for (int row = 0; row < n; ++row)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) dst(3 * row + a, 3 * col + b) += Kstat(3 * row + a, 3 * src + b);
    }
    int d = 0;
    for (int i = 0; i < 8; ++i)
      for (unsigned q : at_corner[i]) {
        for (int a = 0; a < 3; ++a) A(3 * ass[q] + a, 3 * (n - nheld + d) + a) += -1.0;
        ++d;
      }
    const Mat Ainv = A.inverse();
    const Mat Ainvf = Ainv.block(0, 0, 3 * (n - nheld), 3 * n);
    // H ties the held points at one corner together: W is 27-ish × 8.
    Mat H = Mat::Zero(3 * nheld, 24);
    for (int i = 0; i < 8; ++i)
      for (unsigned q : at_corner[i])
        for (int a = 0; a < 3; ++a) H(3 * cut[q] + a, 3 * i + a) = 1;
    const Mat W = -Ainvf * Kg * H;
    Mat WB = Mat::Zero(3 * n, 24);
    for (const auto& [q, cc] : corner_of) {
      const int l = ass[q];
      if (cc >= 0) {
        for (int a = 0; a < 3; ++a) WB(3 * l + a, 3 * cc + a) += 1.0;
      } else {
        for (int j = 0; j < 24; ++j)
          for (int a = 0; a < 3; ++a) WB(3 * l + a, j) += W(3 * cut[q] + a, j);
      }
    }
    Mat WBmeca = Mat::Zero(3 * n, 24);
    for (int i = 0; i < 3 * n; ++i)
      for (int j = 0; j < 24; ++j)
        if (mask(i, j) != 0) WBmeca(i, j) = WB(i, j);
    for (int i = 0; i < 3 * n; ++i) {
      double sum = 0.0;
      for (int j = 0; j < 24; ++j) sum += WBmeca(i, j);
      for (int j = 0; j < 24; ++j) WBmeca(i, j) = WBmeca(i, j) / sum;
    }
    const Mat Kc = WBmeca.transpose() * Kass * WBmeca;
    const Mat Mc = WBmeca.transpose() * Mass * WBmeca;
    K = Kc;
    M = Mc;
    if (!complete) WB = WBmeca;

    std::vector<Weight>& Wk = weights[static_cast<std::size_t>(levels - k - 1)];
    for (int o = 0; o < 8; ++o)
      for (int kid : kids[o]) {
        const Hexa& fh = F.hexas[static_cast<unsigned>(kid)];
        Weight& w = Wk[static_cast<std::size_t>(kid)];
        for (int c = 0; c < 8; ++c)
          for (int a = 0; a < 3; ++a)
            for (int j = 0; j < 24; ++j) w(3 * c + a, j) = WB(3 * ass[fh[c]] + a, j);
      }
  }

  // SOFA's computeFinalWeightsRamification: one level down by the ramified children, then (its
  // quirk, kept) by the unramified cube maps.
  void final_ramified(const Weight& W, unsigned coarse, int e, int level) {
    if (e < 0) return;
    const Weight A = mat_mul(weights[static_cast<std::size_t>(levels - level)][static_cast<std::size_t>(e)], W);
    if (level == levels) {
      (*final_weights)[static_cast<std::size_t>(e)] = {coarse, A};
      return;
    }
    const auto L = grid.ramified_level(level);
    for (const auto& kids : L.children[static_cast<std::size_t>(e)])
      for (int kid : kids) final_plain(A, coarse, kid, level + 1);
  }
  void final_plain(const Weight& W, unsigned coarse, int e, int level) {
    if (e < 0) return;
    const auto& We = weights[static_cast<std::size_t>(levels - level)];
    if (static_cast<std::size_t>(e) >= We.size()) return;
    const Weight A = mat_mul(We[static_cast<std::size_t>(e)], W);
    if (level == levels) {
      (*final_weights)[static_cast<std::size_t>(e)] = {coarse, A};
      return;
    }
    const auto L = grid.ramified_level(level);
    if (static_cast<std::size_t>(e) >= L.cube_map.size()) return;
    for (int kid : L.cube_map[static_cast<std::size_t>(e)]) final_plain(A, coarse, kid, level + 1);
  }
};

}  // namespace

void HexahedronCompositeFEMForceFieldAndMass::init() {
  NonUniformHexahedronFEMForceFieldAndMass::init();
  if (state() != ComponentState::valid) return;
  if (draw_size.value() == -1.0f)
    if (const auto* grid = dynamic_cast<const SparseGridTopology*>(topology.get()))
      draw_size.set(static_cast<float>((grid->max.value()[0] - grid->min.value()[0]) * .004f));
}

bool HexahedronCompositeFEMForceFieldAndMass::compute_element_matrices(const SparseGridTopology& grid, int levels) {
  const std::size_t ne = fem_.size();
  final_weights_.clear();
  component_mass_.clear();
  nodal_mass_.clear();
  if (levels > 0 && grid.nb_virtual_finer_levels.value() < levels) {
    msg_warning("the sparse grid " + grid.describe() + " has " + std::to_string(grid.nb_virtual_finer_levels.value()) +
                " virtual finer levels, fewer than nbVirtualFinerLevels = " + std::to_string(levels) +
                ": the grid's cells get the classical (uniform) matrices");
    levels = 0;
  }
  if (levels == 0) {
    // The classical matrices of each cell, its own material, stiffness and mass coefficients.
    nodal_mass_.assign(ne, Mass8{});
    const std::vector<Hexa>& hexas = grid.hexahedra();
    const double integral = hexa_mass_integral(density.value());
    for (std::size_t e = 0; e < ne; ++e) {
      std::array<Vec3, 8> nodes;
      for (int w = 0; w < 8; ++w) nodes[w] = grid.position.value()[hexas[e][w]];
      fem::Mat24 K;
      fem::hexa_element_stiffness(nodes, fem_.material[e], static_cast<double>(grid.stiffness_coef(e)), K);
      fem_.K[e] = K.transpose();
      const double vol = (nodes[1] - nodes[0]).norm() * (nodes[3] - nodes[0]).norm() * (nodes[4] - nodes[0]).norm();
      nodal_mass_[e].fill((vol * integral) * static_cast<double>(grid.mass_coef(e)));
    }
    return true;
  }
  if (finest_to_coarse.value()) {
    msg_error("finestToCoarse is not supported (SOFA's examples homogenize level by level)");
    return false;
  }
  const auto* ramified = dynamic_cast<const SparseGridRamificationTopology*>(&grid);
  if (!use_ramification.value() || !ramified) {
    msg_error(std::string(ramified ? "useRamification=false" : "a sparse grid without ramifications (" +
                                                                   grid.describe() + ")") +
              " is not supported: the composite homogenization follows the ramifications of a "
              "SparseGridRamificationTopology or SparseGridMultipleTopology");
    return false;
  }
  if (ramified->ramified_levels() < levels) {
    msg_error("the sparse grid " + grid.describe() + " keeps " + std::to_string(ramified->ramified_levels()) +
              " ramified virtual levels (none when built with computeRamifications=false), fewer than "
              "nbVirtualFinerLevels = " + std::to_string(levels) + ": not supported");
    return false;
  }

  Homogenizer hom(*ramified, levels, complete_interpolation.value(),
                  [this](const std::array<Vec3, 8>& nodes, double coef, fem::Mat24& K, Mass8& M) {
                    return classical_matrices(nodes, coef, K, M);
                  });
  hom.weights.resize(static_cast<std::size_t>(levels));
  for (int k = 1; k <= levels; ++k)
    hom.weights[static_cast<std::size_t>(levels - k)].assign(ramified->ramified_level(k).hexas.size(),
                                                             Weight::Zero());
  component_mass_.resize(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    fem::Mat24 K, M;
    hom.condense(0, static_cast<unsigned>(e), K, M);
    if (!K.allFinite() || !M.allFinite()) {
      msg_error("hexahedron " + std::to_string(e) +
                ": the homogenization gave non-finite matrices (a singular fine assembly)");
      return false;
    }
    fem_.K[e] = K.transpose();  // the kernel reads columns (see NonUniformHexahedronFEMForceFieldAndMass)
    for (int c = 0; c < 3; ++c)
      for (int w = 0; w < 8; ++w)
        for (int j = 0; j < 8; ++j) component_mass_[e][c][8 * w + j] = M(3 * w + c, 3 * j + c);
  }
  final_weights_.assign(ramified->ramified_level(levels).hexas.size(), FinalWeight{});
  hom.final_weights = &final_weights_;
  const auto top = ramified->ramified_level(0);
  for (std::size_t e = 0; e < ne; ++e)
    for (const auto& kids : top.children[e])
      for (int kid : kids) hom.final_ramified(Weight::Identity(), static_cast<unsigned>(e), kid, 1);
  if (hom.singular > 0)
    msg_warning(std::to_string(hom.singular) + " cells of virtual level " + std::to_string(levels) +
                " have a singular Jacobian");
  return true;
}

void register_hexahedron_composite_fem_force_field_and_mass(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronCompositeFEMForceFieldAndMass";
  info.category = "ForceField/FEM";
  info.description =
      "hexahedral finite elements and mass on a sparse grid of composite material, homogenized from its virtual "
      "finer levels";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedronCompositeFEMForceFieldAndMass>();
  r.add(std::move(info));
}

}  // namespace sinew
