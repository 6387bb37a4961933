#include "topology/grid/sparse_grid_ramification_topology.h"

#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <cmath>
#include <map>

#include "core/registry.h"

namespace sinew {

namespace {

int opposite(int direction) { return direction % 2 == 0 ? direction + 1 : direction - 1; }

// Does the segment cross triangle (t0,t1,t2)? SOFA's test (after Eberly): the line s0 + t·u
// (u the unit direction) is accepted for |t| <= |s1-s0|, i.e. the segment is extended
// backwards by its own length, and a segment parallel to the triangle never crosses it.
bool segment_crosses_triangle(const Vec3& s0, const Vec3& s1, const Vec3& t0, const Vec3& t1, const Vec3& t2) {
  const Vec3 diff = s0 - t0;
  const Vec3 e1 = t1 - t0, e2 = t2 - t0;
  const Vec3 normal = e1.cross(e2);
  const double length = (s1 - s0).norm();
  const Vec3 dir = (s1 - s0) / length;
  double d_dot_n = dir.dot(normal);
  double sign;
  if (d_dot_n > 1e-10) {
    sign = 1;
  } else if (d_dot_n < -1e-10) {
    sign = -1;
    d_dot_n = -d_dot_n;
  } else {
    return false;
  }
  const double b1 = sign * dir.dot(diff.cross(e2));
  if (b1 < 0) return false;
  const double b2 = sign * dir.dot(e1.cross(diff));
  if (b2 < 0 || b1 + b2 > d_dot_n) return false;
  const double q_dot_n = -sign * diff.dot(normal);
  const double extent = length * d_dot_n;
  return -extent <= q_dot_n && q_dot_n <= extent;
}

}  // namespace

// ---------------------------------------------------------------- building

void SparseGridRamificationTopology::generate() {
  climb_lookup_ = false;
  coarsest_of_finest_.clear();
  ram_levels_.clear();
  ram_children_.clear();
  ram_cube_map_.clear();
  VecNi<3> dims;
  std::vector<Vec3> vertices;
  std::vector<std::vector<unsigned>> facets;
  if (!prepare(dims, vertices, facets)) return;
  const int levels = nb_virtual_finer_levels.value();
  const bool finest = finest_connectivity.value();

  if (levels == 0) {
    RamLevel L;
    if (!build_from_surface(L.level, dims, min.get(), max.get(), cell_width.value(), only_inside_cells.value(),
                            vertices, facets)) {
      build_failed_ = true;
      return;
    }
    if (finest && !L.level.hexas.empty()) {
      link_finest(L, true, vertices, facets);
      ramify_finest(L);
    }
    // Look-ups stay those of SparseGridTopology (unramified cell indices), as in SOFA.
    adopt(std::move(L.level));
    return;
  }

  // Virtual finer levels: the finest one is built from the surface, then coarsened.
  std::vector<RamLevel> chain(static_cast<std::size_t>(levels) + 1);
  RamLevel& fine = chain[0];
  if (!build_from_surface(fine.level, finest_dims(dims, levels), min.get(), max.get(), 0.0, false, vertices, facets)) {
    build_failed_ = true;
    return;
  }
  if (fine.level.hexas.empty()) {
    adopt(std::move(fine.level));  // init() reports the empty grid
    return;
  }
  link_finest(fine, finest, vertices, facets);
  if (finest) ramify_finest(fine);
  for (std::size_t i = 1; i < chain.size(); ++i) coarsen_ramified(chain[i - 1], chain[i]);

  // Each finest cell → the hexahedron of the coarsest parent of its first connexion.
  coarsest_of_finest_.assign(fine.cell_connexions.size(), kInvalidIndex);
  for (std::size_t c = 0; c < fine.cell_connexions.size(); ++c) {
    int id = fine.cell_connexions[c].front();
    std::size_t lvl = 0;
    while (chain[lvl].connexions[static_cast<std::size_t>(id)].parent >= 0) {
      id = chain[lvl].connexions[static_cast<std::size_t>(id)].parent;
      ++lvl;
    }
    coarsest_of_finest_[c] = static_cast<unsigned>(chain[lvl].connexions[static_cast<std::size_t>(id)].hexa);
  }
  climb_lookup_ = true;
  finest_grid_ = fine.level.grid;
  finest_sparse_of_regular_ = fine.level.sparse_of_regular;
  finest_points_ = fine.level.points;
  finest_hexas_ = fine.level.hexas;
  finest_types_ = fine.level.types;

  // The hierarchy, for the composite FEM: each coarser hexahedron's children by octant, in the
  // order of its connexion's children (SOFA's _hierarchicalCubeMapRamification).
  ram_children_.resize(chain.size());
  ram_cube_map_.resize(chain.size());
  for (std::size_t j = 1; j < chain.size(); ++j) {
    auto& children = ram_children_[j];
    children.assign(chain[j].level.hexas.size(), {});
    for (const Connexion& cx : chain[j].connexions)
      for (const auto& [place, fc] : cx.children)
        children[static_cast<std::size_t>(cx.hexa)][static_cast<std::size_t>(place)].push_back(
            chain[j - 1].connexions[static_cast<std::size_t>(fc)].hexa);
    ram_cube_map_[j] = std::move(chain[j].cube_map);
  }
  for (std::size_t j = 0; j + 1 < chain.size(); ++j) ram_levels_.push_back(std::move(chain[j].level));
  adopt(std::move(chain.back().level));
}

void SparseGridRamificationTopology::link_finest(RamLevel& L, bool test_surface, const std::vector<Vec3>& vertices,
                                                 const std::vector<std::vector<unsigned>>& facets) const {
  const std::size_t nc = L.level.hexas.size();
  L.connexions.assign(nc, Connexion{});
  L.cell_connexions.assign(nc, {});
  for (std::size_t c = 0; c < nc; ++c) {
    L.cell_connexions[c].push_back(static_cast<int>(c));
    L.connexions[c].cell = static_cast<int>(c);
    L.connexions[c].hexa = static_cast<int>(c);
  }
  const Level& lv = L.level;
  // Two boundary cells are linked only if a surface edge (consecutive facet vertices; the
  // closing edge is not tested, as in SOFA) crosses their common face.
  auto linked = [&](int cell, int neighbour, int direction) {
    if (!test_surface) return true;
    if (lv.types[static_cast<std::size_t>(cell)] != CellType::boundary ||
        lv.types[static_cast<std::size_t>(neighbour)] != CellType::boundary)
      return true;
    const Hexa& h = lv.hexas[static_cast<std::size_t>(cell)];
    static constexpr int kFace[3][4] = {{0, 4, 7, 3}, {0, 1, 5, 4}, {0, 1, 2, 3}};  // x-, y-, z- faces
    const int f = direction == kLeft ? 0 : direction == kDown ? 1 : 2;
    const Vec3& a = lv.points[h[kFace[f][0]]];
    const Vec3& b = lv.points[h[kFace[f][1]]];
    const Vec3& c = lv.points[h[kFace[f][2]]];
    const Vec3& d = lv.points[h[kFace[f][3]]];
    for (const auto& facet : facets)
      for (std::size_t j = 1; j < facet.size(); ++j) {
        const Vec3& A = vertices[facet[j - 1]];
        const Vec3& B = vertices[facet[j]];
        if (segment_crosses_triangle(A, B, a, b, c) || segment_crosses_triangle(A, B, a, c, d)) return true;
      }
    return false;
  };
  const Grid& g = lv.grid;
  auto link = [&](int cell, int x, int y, int z, int direction) {
    const int neighbour = lv.sparse_of_regular[static_cast<std::size_t>(g.cube(x, y, z))];
    if (neighbour < 0 || !linked(cell, neighbour, direction)) return;
    L.connexions[static_cast<std::size_t>(cell)].neighbours[static_cast<std::size_t>(direction)].insert(neighbour);
    L.connexions[static_cast<std::size_t>(neighbour)].neighbours[static_cast<std::size_t>(opposite(direction))].insert(
        cell);
  };
  for (int z = 0; z < g.n[2] - 1; ++z)
    for (int y = 0; y < g.n[1] - 1; ++y)
      for (int x = 0; x < g.n[0] - 1; ++x) {
        const int cell = lv.sparse_of_regular[static_cast<std::size_t>(g.cube(x, y, z))];
        if (cell < 0) continue;
        if (x > 0) link(cell, x - 1, y, z, kLeft);
        if (y > 0) link(cell, x, y - 1, z, kDown);
        if (z > 0) link(cell, x, y, z - 1, kBefore);
      }
}

void SparseGridRamificationTopology::ramify_finest(RamLevel& L) {
  std::vector<std::array<Vec3, 8>> corners(L.level.hexas.size());
  for (std::size_t c = 0; c < corners.size(); ++c)
    for (int k = 0; k < 8; ++k) corners[c][static_cast<std::size_t>(k)] = L.level.points[L.level.hexas[c][k]];
  // Types and coefficients keep their unramified lists (SOFA does not update them here).
  build_hexahedra(L, corners);
}

void SparseGridRamificationTopology::build_hexahedra(RamLevel& L, const std::vector<std::array<Vec3, 8>>& corners) {
  // One hexahedron per connexion, in (cell, connexion) order, with 8 fresh point labels.
  std::vector<Hexa> hexas;
  for (std::size_t c = 0; c < L.cell_connexions.size(); ++c)
    for (int id : L.cell_connexions[c]) {
      Connexion& cx = L.connexions[static_cast<std::size_t>(id)];
      cx.hexa = static_cast<int>(hexas.size());
      cx.cell = static_cast<int>(c);
      const auto base = static_cast<unsigned>(hexas.size() * 8);
      hexas.push_back(Hexa{base, base + 1, base + 2, base + 3, base + 4, base + 5, base + 6, base + 7});
    }
  // Merging the corners of a linked face relabels every slot holding the old label (SOFA's
  // changeIndices); members[label] lists the slots (hexa·8 + corner) holding it.
  const std::size_t nslots = hexas.size() * 8;
  std::vector<std::vector<unsigned>> members(nslots);
  for (std::size_t s = 0; s < nslots; ++s) members[s].push_back(static_cast<unsigned>(s));
  auto merge = [&](unsigned from, unsigned to) {
    if (from == to) return;
    for (unsigned s : members[from]) hexas[s / 8][s % 8] = to;
    members[to].insert(members[to].end(), members[from].begin(), members[from].end());
    members[from].clear();
  };
  // Corner pairs of a face shared with the neighbour in direction BEFORE (z-), DOWN (y-), LEFT (x-).
  static constexpr int kPairs[3][4][2] = {
      {{0, 4}, {1, 5}, {2, 6}, {3, 7}}, {{0, 3}, {4, 7}, {5, 6}, {1, 2}}, {{0, 1}, {4, 5}, {7, 6}, {3, 2}}};
  static constexpr int kDirs[3] = {kBefore, kDown, kLeft};
  for (const auto& ids : L.cell_connexions)
    for (int id : ids) {
      const Connexion& cx = L.connexions[static_cast<std::size_t>(id)];
      for (int d = 0; d < 3; ++d)
        for (int nb : cx.neighbours[static_cast<std::size_t>(kDirs[d])]) {
          const int h = cx.hexa, hn = L.connexions[static_cast<std::size_t>(nb)].hexa;
          for (const auto& pair : kPairs[d])
            merge(hexas[static_cast<std::size_t>(h)][pair[0]], hexas[static_cast<std::size_t>(hn)][pair[1]]);
        }
    }
  // Used labels renumbered in increasing order; a point sits at the corner of its first slot.
  std::vector<unsigned> cell_of_hexa(hexas.size());
  for (const Connexion& cx : L.connexions)
    cell_of_hexa[static_cast<std::size_t>(cx.hexa)] = static_cast<unsigned>(cx.cell);
  std::vector<unsigned> renumber(nslots, 0);
  L.level.points.clear();
  for (std::size_t label = 0; label < nslots; ++label) {
    if (members[label].empty()) continue;
    const unsigned first = *std::min_element(members[label].begin(), members[label].end());
    renumber[label] = static_cast<unsigned>(L.level.points.size());
    L.level.points.push_back(corners[cell_of_hexa[first / 8]][first % 8]);
  }
  for (Hexa& h : hexas)
    for (int k = 0; k < 8; ++k) h[k] = renumber[h[k]];
  L.level.hexas = std::move(hexas);
}

void SparseGridRamificationTopology::coarsen_ramified(RamLevel& fine, RamLevel& coarse) {
  // The coarse grid as in SparseGridTopology::coarsen: the same box, twice the cell size.
  const Level& fl = fine.level;
  const VecNi<3> fn = fl.grid.n;
  const VecNi<3> cn(fn[0] / 2 + 1, fn[1] / 2 + 1, fn[2] / 2 + 1);
  Level& cl = coarse.level;
  cl.min = fl.min;
  cl.max = Vec3(cl.min[0] + (cn[0] - 1) * 2.0 * fl.grid.dx[0], cl.min[1] + (cn[1] - 1) * 2.0 * fl.grid.dy[1],
                cl.min[2] + (cn[2] - 1) * 2.0 * fl.grid.dz[2]);
  cl.grid.set(cn, cl.min, cl.max);
  cl.sparse_of_regular.assign(static_cast<std::size_t>(cl.grid.nb_cells()), -1);

  // Unramified coarse cells (x outer, then y, then z), typed from their 8 children. The fine
  // types are read with unramified indices from the per-hexahedron list, as SOFA does.
  auto fine_type = [&](int idx) {
    return static_cast<std::size_t>(idx) < fl.types.size() ? fl.types[static_cast<std::size_t>(idx)]
                                                           : CellType::outside;
  };
  std::vector<CellType> cell_types;
  std::vector<std::array<int, 8>> cell_children;
  std::vector<std::array<Vec3, 8>> corners;
  for (int i = 0; i < cn[0] - 1; ++i)
    for (int j = 0; j < cn[1] - 1; ++j)
      for (int k = 0; k < cn[2] - 1; ++k) {
        std::array<int, 8> children{};
        for (int idx = 0; idx < 8; ++idx) {
          const int x = 2 * i + (idx & 1), y = 2 * j + (idx & 2) / 2, z = 2 * k + (idx & 4) / 4;
          children[static_cast<std::size_t>(idx)] =
              x < fn[0] - 1 && y < fn[1] - 1 && z < fn[2] - 1
                  ? fl.sparse_of_regular[static_cast<std::size_t>(fl.grid.cube(x, y, z))]
                  : -1;
        }
        bool inside = true, outside = true;
        for (int w = 0; w < 8 && (inside || outside); ++w) {
          const int ch = children[static_cast<std::size_t>(w)];
          if (ch < 0)
            inside = false;
          else if (fine_type(ch) == CellType::boundary)
            inside = outside = false;
          else if (fine_type(ch) == CellType::inside)
            outside = false;
        }
        if (outside) continue;
        cl.sparse_of_regular[static_cast<std::size_t>(cl.grid.cube(i, j, k))] = static_cast<int>(cell_types.size());
        cell_types.push_back(inside ? CellType::inside : CellType::boundary);
        cell_children.push_back(children);
        std::array<Vec3, 8> c;
        for (int w = 0; w < 8; ++w)
          c[static_cast<std::size_t>(w)] = cl.grid.point(i + kHexaCorner[w][0], j + kHexaCorner[w][1], k + kHexaCorner[w][2]);
        corners.push_back(c);
      }

  // Each coarse cell gets one connexion per connected component of its children's connexions
  // (components numbered by their first member in child order).
  const std::size_t ncells = cell_types.size();
  coarse.cell_connexions.assign(ncells, {});
  coarse.connexions.clear();
  std::vector<int> block(fine.connexions.size(), -1);  // coarse cell being grouped, per fine connexion
  std::vector<int> stack;
  for (std::size_t idx = 0; idx < ncells; ++idx) {
    std::vector<std::pair<int, int>> members;  // (place, fine connexion)
    for (int place = 0; place < 8; ++place) {
      const int ch = cell_children[idx][static_cast<std::size_t>(place)];
      if (ch < 0) continue;
      for (int fc : fine.cell_connexions[static_cast<std::size_t>(ch)]) {
        members.emplace_back(place, fc);
        fine.connexions[static_cast<std::size_t>(fc)].tmp = -1;
        block[static_cast<std::size_t>(fc)] = static_cast<int>(idx);
      }
    }
    for (std::size_t m = 0; m < members.size(); ++m) {
      stack.assign(1, members[m].second);
      while (!stack.empty()) {
        Connexion& cx = fine.connexions[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (cx.tmp != -1) continue;
        cx.tmp = static_cast<int>(m);
        for (const auto& dir : cx.neighbours)
          for (int nb : dir)
            if (block[static_cast<std::size_t>(nb)] == static_cast<int>(idx)) stack.push_back(nb);
      }
    }
    std::map<int, int> coarse_of_number;
    for (const auto& [place, fc] : members)
      coarse_of_number.emplace(fine.connexions[static_cast<std::size_t>(fc)].tmp, 0);
    for (auto& [number, id] : coarse_of_number) {
      id = static_cast<int>(coarse.connexions.size());
      coarse.connexions.emplace_back();
      coarse.connexions.back().cell = static_cast<int>(idx);
      coarse.cell_connexions[idx].push_back(id);
    }
    for (const auto& [place, fc] : members) {
      Connexion& f = fine.connexions[static_cast<std::size_t>(fc)];
      const int id = coarse_of_number[f.tmp];
      coarse.connexions[static_cast<std::size_t>(id)].children.emplace_back(place, fc);
      f.parent = id;
    }
  }

  // Coarse connexions are linked when children in different coarse cells are.
  for (const Connexion& f : fine.connexions)
    for (int d = 0; d < kNbDirections; ++d)
      for (int nb : f.neighbours[static_cast<std::size_t>(d)]) {
        const int c1 = f.parent, c2 = fine.connexions[static_cast<std::size_t>(nb)].parent;
        if (coarse.connexions[static_cast<std::size_t>(c1)].cell ==
            coarse.connexions[static_cast<std::size_t>(c2)].cell)
          continue;
        coarse.connexions[static_cast<std::size_t>(c1)].neighbours[static_cast<std::size_t>(d)].insert(c2);
        coarse.connexions[static_cast<std::size_t>(c2)].neighbours[static_cast<std::size_t>(opposite(d))].insert(c1);
      }

  build_hexahedra(coarse, corners);

  // Types and children per hexahedron. A split cell is boundary; SOFA keeps, per split
  // hexahedron, only its last child (the child loop overwrites the 8 slots each time), and
  // reads the fine coefficients of an unsplit cell with unramified indices: both kept so that
  // the coefficients match.
  const std::size_t nh = cl.hexas.size();
  std::vector<std::array<int, 8>> hexa_children;
  hexa_children.reserve(nh);
  cl.types.clear();
  for (std::size_t idx = 0; idx < ncells; ++idx) {
    const auto& ids = coarse.cell_connexions[idx];
    if (ids.size() == 1) {
      hexa_children.push_back(cell_children[idx]);
      cl.types.push_back(cell_types[idx]);
      continue;
    }
    for (int id : ids) {
      std::array<int, 8> slots;
      slots.fill(-1);
      for (const auto& [place, fc] : coarse.connexions[static_cast<std::size_t>(id)].children) {
        const Connexion& f = fine.connexions[static_cast<std::size_t>(fc)];
        for (int p = 0; p < 8; ++p)
          slots[static_cast<std::size_t>(p)] = f.cell == cell_children[idx][static_cast<std::size_t>(p)] ? f.hexa : -1;
      }
      hexa_children.push_back(slots);
      cl.types.push_back(CellType::boundary);
    }
  }
  coarse.cube_map = hexa_children;
  auto coef = [](const std::vector<float>& list, int i) {
    return static_cast<std::size_t>(i) < list.size() ? list[static_cast<std::size_t>(i)] : 1.0f;
  };
  cl.stiffness.assign(nh, 0.0f);
  cl.mass.assign(nh, 0.0f);
  for (std::size_t h = 0; h < nh; ++h) {
    for (int child : hexa_children[h])
      if (child >= 0) {
        cl.stiffness[h] += coef(fl.stiffness, child);
        cl.mass[h] += coef(fl.mass, child);
      }
    cl.stiffness[h] /= 8.0f;
    cl.mass[h] /= 8.0f;
  }
}

// ---------------------------------------------------------------- hierarchy

int SparseGridRamificationTopology::ramified_levels() const {
  nb_points();  // builds the grid first
  return static_cast<int>(ram_levels_.size());
}

SparseGridRamificationTopology::RamifiedLevel SparseGridRamificationTopology::ramified_level(int k) const {
  const int L = ramified_levels();
  if (k <= 0 || L == 0) {
    const std::size_t j = ram_children_.empty() ? 0 : ram_children_.size() - 1;
    RamifiedLevel r{position.get(), hexahedra(), stiffness_coefs_, mass_coefs_, {}, {}};
    if (!ram_children_.empty()) r.children = ram_children_[j], r.cube_map = ram_cube_map_[j];
    return r;
  }
  const std::size_t j = static_cast<std::size_t>(L - std::min(k, L));
  const Level& lv = ram_levels_[j];
  return {lv.points, lv.hexas, lv.stiffness, lv.mass, ram_children_[j], ram_cube_map_[j]};
}

unsigned SparseGridRamificationTopology::find_cube_on_level(int k, const Vec3& p, double& fx, double& fy,
                                                            double& fz) const {
  const int L = ramified_levels();
  if (k <= 0 || k > L) return kInvalidIndex;
  const Level& lv = ram_levels_[static_cast<std::size_t>(L - k)];
  double x, y, z;
  const int c = lv.grid.find(p, x, y, z);
  if (c < 0) return kInvalidIndex;
  fx = x - std::floor(x);
  fy = y - std::floor(y);
  fz = z - std::floor(z);
  const int s = lv.sparse_of_regular[static_cast<std::size_t>(c)];
  return s < 0 ? kInvalidIndex : static_cast<unsigned>(s);
}

unsigned SparseGridRamificationTopology::find_nearest_cube_on_level(int k, const Vec3& p, double& fx, double& fy,
                                                                    double& fz) const {
  const int L = ramified_levels();
  if (k <= 0 || k > L) return kInvalidIndex;
  const Level& lv = ram_levels_[static_cast<std::size_t>(L - k)];
  return nearest_boundary_cube(lv.points, lv.hexas, lv.types, p, fx, fy, fz);
}

// ---------------------------------------------------------------- look-ups

unsigned SparseGridRamificationTopology::find_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  nb_points();
  if (!climb_lookup_) return SparseGridTopology::find_cube(p, fx, fy, fz);
  double x, y, z;
  const int c = finest_grid_.find(p, x, y, z);
  if (c < 0) return kInvalidIndex;
  const int s = finest_sparse_of_regular_[static_cast<std::size_t>(c)];
  if (s < 0) return kInvalidIndex;
  // Local coordinates in this grid's regular cell (the finest grid lies inside it).
  if (grid_.find(p, x, y, z) >= 0) {
    fx = x - std::floor(x);
    fy = y - std::floor(y);
    fz = z - std::floor(z);
  }
  return coarsest_of_finest_[static_cast<std::size_t>(s)];
}

unsigned SparseGridRamificationTopology::find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  nb_points();
  if (!climb_lookup_) return SparseGridTopology::find_nearest_cube(p, fx, fy, fz);
  const unsigned s = nearest_boundary_cube(finest_points_, finest_hexas_, finest_types_, p, fx, fy, fz);
  if (s >= coarsest_of_finest_.size()) return kInvalidIndex;
  // Local coordinates in the nearest regular cell of this grid: the cell index is clamped, the
  // coordinates are not (extrapolation), as RegularGridTopology::findNearestCube.
  const Vec3 d = p - grid_.p0;
  const double x = d.dot(grid_.dx) * grid_.inv_dx2, y = d.dot(grid_.dy) * grid_.inv_dy2,
               z = d.dot(grid_.dz) * grid_.inv_dz2;
  const int ix = std::clamp(static_cast<int>(std::floor(x)), 0, grid_.n[0] - 2);
  const int iy = std::clamp(static_cast<int>(std::floor(y)), 0, grid_.n[1] - 2);
  const int iz = std::clamp(static_cast<int>(std::floor(z)), 0, grid_.n[2] - 2);
  fx = x - ix;
  fy = y - iy;
  fz = z - iz;
  return coarsest_of_finest_[s];
}

void register_sparse_grid_ramification_topology(Registry& r) {
  ComponentInfo info;
  info.name = "SparseGridRamificationTopology";
  info.category = "Topology";
  info.description = "Sparse grid in 3D whose cells are split where the surface pieces they cover are not connected";
  info.aliases = {"SparseGridRamification"};
  info.create = creator<SparseGridRamificationTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
