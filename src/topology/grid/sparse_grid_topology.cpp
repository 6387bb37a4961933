#include "topology/grid/sparse_grid_topology.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/alloc_check.h"
#include "core/registry.h"
#include "io/mesh_readers.h"

namespace sinew {

namespace {

// ---------------------------------------------------------------- triangle / cube test
// "Fast polygon-cube intersection" (Hatch & Green, Graphics Gems V) against the cube
// [-0.5, 0.5]³, in single precision as SOFA uses it; comparisons against the
// double limits are done in double, as in the C original.

// Outcode bits of `value` against the pair of planes ±limit (only the bits still in `mask`).
inline void test_planes(unsigned long mask, unsigned long pos, unsigned long neg, float value, double limit,
                        unsigned long& out) {
  if (mask & (pos | neg)) {
    if ((mask & pos) && value > limit) out |= pos;
    else if ((mask & neg) && value < -limit) out |= neg;
  }
}

unsigned long face_planes(const float p[3], unsigned long mask) {
  unsigned long out = 0;
  test_planes(mask, 0x001, 0x002, p[0], 0.5, out);
  test_planes(mask, 0x004, 0x008, p[1], 0.5, out);
  test_planes(mask, 0x010, 0x020, p[2], 0.5, out);
  return out;
}

unsigned long edge_planes(const float p[3], unsigned long mask) {
  unsigned long out = 0;
  test_planes(mask, 0x001, 0x002, p[0] + p[1], 1.0, out);
  test_planes(mask, 0x004, 0x008, p[0] - p[1], 1.0, out);
  test_planes(mask, 0x010, 0x020, p[0] + p[2], 1.0, out);
  test_planes(mask, 0x040, 0x080, p[0] - p[2], 1.0, out);
  test_planes(mask, 0x100, 0x200, p[1] + p[2], 1.0, out);
  test_planes(mask, 0x400, 0x800, p[1] - p[2], 1.0, out);
  return out;
}

unsigned long corner_planes(const float p[3], unsigned long mask) {
  unsigned long out = 0;
  test_planes(mask, 0x001, 0x002, p[0] + p[1] + p[2], 1.5, out);
  test_planes(mask, 0x004, 0x008, p[0] + p[1] - p[2], 1.5, out);
  test_planes(mask, 0x010, 0x020, p[0] - p[1] + p[2], 1.5, out);
  test_planes(mask, 0x040, 0x080, p[0] - p[1] - p[2], 1.5, out);
  return out;
}

// 1: a vertex is inside (accept); 0: all vertices beyond one plane (reject); -1: undecided.
int trivial_tests(int nv, const float v[][3]) {
  unsigned long all = ~0UL;
  for (int i = 0; i < nv; ++i) {
    const unsigned long bits = face_planes(v[i], ~0UL);
    if (bits == 0) return 1;
    all &= bits;
  }
  if (all != 0) return 0;
  all = ~0UL;
  for (int i = 0; i < nv; ++i)
    if ((all = edge_planes(v[i], all)) == 0) break;
  if (all != 0) return 0;
  all = ~0UL;
  for (int i = 0; i < nv; ++i)
    if ((all = corner_planes(v[i], all)) == 0) break;
  if (all != 0) return 0;
  return -1;
}

inline int sign_nonzero(float x) { return x < 0 ? -1 : 1; }

bool segment_intersects_cube(const float a[3], const float b[3]) {
  float e[3];
  int s[3];
  for (int i = 0; i < 3; ++i) {
    e[i] = b[i] - a[i];
    s[i] = sign_nonzero(e[i]);
  }
  for (int i = 0; i < 3; ++i) {
    if (a[i] * s[i] > .5) return false;
    if (b[i] * s[i] < -.5) return false;
  }
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    const float n_dot_a = e[i2] * a[i1] - e[i1] * a[i2];
    const float n_dot_edge = .5f * (e[i2] * s[i1] + e[i1] * s[i2]);
    if (n_dot_a * n_dot_a > n_dot_edge * n_dot_edge) return false;
  }
  return true;
}

// Winding number of `p` in the polygon projected along its dominant normal axis.
int polygon_contains_point(int nv, const float v[][3], const float normal[3], const float p[3]) {
  float a[3];
  for (int i = 0; i < 3; ++i) a[i] = normal[i] < 0 ? -normal[i] : normal[i];
  const int zaxis = a[0] > a[2] ? (a[0] > a[1] ? 0 : 1) : (a[1] > a[2] ? 1 : 2);
  int xaxis, yaxis;
  if (normal[zaxis] < 0) {
    xaxis = (zaxis + 2) % 3;
    yaxis = (zaxis + 1) % 3;
  } else {
    xaxis = (zaxis + 1) % 3;
    yaxis = (zaxis + 2) % 3;
  }
  auto crosses = [](float lo, float hi, float x) { return static_cast<int>(hi > x) - static_cast<int>(lo > x); };
  int count = 0;
  for (int i = 0; i < nv; ++i) {
    const float* u = v[i];
    const float* w = v[(i + 1) % nv];
    if (const int xdir = crosses(u[xaxis], w[xaxis], p[xaxis])) {
      if (crosses(u[yaxis], w[yaxis], p[yaxis])) {
        if (xdir * (p[xaxis] - u[xaxis]) * (w[yaxis] - u[yaxis]) <= xdir * (p[yaxis] - u[yaxis]) * (w[xaxis] - u[xaxis]))
          count += xdir;
      } else if (u[yaxis] <= p[yaxis]) {
        count += xdir;
      }
    }
  }
  return count;
}

bool polygon_intersects_cube(int nv, const float v[][3], const float normal[3]) {
  for (int i = 0; i < nv; ++i)
    if (segment_intersects_cube(v[i], v[(i + 1) % nv])) return true;
  if (normal[0] == 0 && normal[1] == 0 && normal[2] == 0) return false;
  int d[3];
  for (int i = 0; i < 3; ++i) d[i] = sign_nonzero(normal[i]);
  const float t = (normal[0] * v[0][0] + normal[1] * v[0][1] + normal[2] * v[0][2]) /
                  (normal[0] * d[0] + normal[1] * d[1] + normal[2] * d[2]);
  if (!((t - (-.5)) * (t - .5) <= 0)) return false;
  const float p[3] = {t * d[0], t * d[1], t * d[2]};
  return polygon_contains_point(nv, v, normal, p) != 0;
}

bool triangle_intersects_cube(const float v[3][3]) {
  // Normal: sum of the fan triangles' cross products (one triangle here).
  float e1[3], e2[3], normal[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = v[1][i] - v[0][i];
    e2[i] = v[2][i] - v[0][i];
  }
  normal[0] = 0 + (e1[1] * e2[2] - e1[2] * e2[1]);
  normal[1] = 0 + (e1[2] * e2[0] - e1[0] * e2[2]);
  normal[2] = 0 + (e1[0] * e2[1] - e1[1] * e2[0]);
  const int quick = trivial_tests(3, v);
  if (quick != -1) return quick == 1;
  return polygon_intersects_cube(3, v, normal);
}

// Lexicographic (x, then y, then z) order of corner positions: the point numbering.
struct Lexicographic {
  bool operator()(const Vec3& a, const Vec3& b) const {
    for (int i = 0; i < 3; ++i) {
      if (a[i] < b[i]) return true;
      if (a[i] > b[i]) return false;
    }
    return false;
  }
};

}  // namespace

// ---------------------------------------------------------------- grid

void SparseGridTopology::Grid::set(const VecNi<3>& dims, const Vec3& lo, const Vec3& hi) {
  // RegularGridTopology::setSize + setPos (every axis has at least 2 points here).
  n = dims;
  p0 = lo;
  dx = Vec3((hi[0] - lo[0]) / (n[0] - 1), 0, 0);
  dy = Vec3(0, (hi[1] - lo[1]) / (n[1] - 1), 0);
  dz = Vec3(0, 0, (hi[2] - lo[2]) / (n[2] - 1));
  inv_dx2 = 1 / dx.dot(dx);
  inv_dy2 = 1 / dy.dot(dy);
  inv_dz2 = 1 / dz.dot(dz);
}

int SparseGridTopology::Grid::find(const Vec3& pos, double& x, double& y, double& z) const {
  if (n[0] < 2 || n[1] < 2 || n[2] < 2) return -1;
  const Vec3 p = pos - p0;
  auto dot = [&](const Vec3& d) { return p[0] * d[0] + p[1] * d[1] + p[2] * d[2]; };
  x = dot(dx) * inv_dx2;
  y = dot(dy) * inv_dy2;
  z = dot(dz) * inv_dz2;
  const int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y)),
            iz = static_cast<int>(std::floor(z));
  if (static_cast<unsigned>(ix) <= static_cast<unsigned>(n[0] - 2) &&
      static_cast<unsigned>(iy) <= static_cast<unsigned>(n[1] - 2) &&
      static_cast<unsigned>(iz) <= static_cast<unsigned>(n[2] - 2))
    return cube(ix, iy, iz);
  return -1;
}

// ---------------------------------------------------------------- building

void SparseGridTopology::init() {
  nb_points();  // builds the grid (lazily, so that a state initialised earlier already saw it)
  if (build_failed_ || hexahedra().empty()) {
    if (!build_failed_) msg_error("the sparse grid has no cell");
    set_state(ComponentState::invalid);
  }
}

void SparseGridTopology::generate() {
  VecNi<3> dims;
  std::vector<Vec3> vertices;
  std::vector<std::vector<unsigned>> facets;
  if (!prepare(dims, vertices, facets)) return;
  Level level;
  const int levels = nb_virtual_finer_levels.value();
  if (levels == 0) {
    if (!build_from_surface(level, dims, min.get(), max.get(), cell_width.value(), only_inside_cells.value(), vertices,
                            facets)) {
      build_failed_ = true;
      return;
    }
  } else {
    // Virtual finer levels: the finest grid has (n-1)·2^levels + 1 points per axis (same box),
    // then it is coarsened `levels` times.
    // The virtual levels are kept (finest first) for the components that integrate over them.
    std::vector<Level> finer(static_cast<std::size_t>(levels));
    if (!build_from_surface(finer[0], finest_dims(dims, levels), min.get(), max.get(), 0.0, false, vertices,
                            facets)) {
      build_failed_ = true;
      return;
    }
    for (std::size_t i = 1; i < finer.size(); ++i) coarsen(finer[i - 1], finer[i]);
    coarsen(finer.back(), level);
    virtual_levels_ = std::move(finer);
  }
  adopt(std::move(level));
}

int SparseGridTopology::kept_levels() const {
  nb_points();  // builds the grid first
  return children_.empty() ? 0 : static_cast<int>(virtual_levels_.size());
}

SparseGridTopology::LevelView SparseGridTopology::level(int k) const {
  const std::vector<Hexa>& hexas = hexahedra();  // builds the grid first
  if (k <= 0) return {position.get(), hexas, stiffness_coefs_, children_};
  const Level& L = virtual_levels_[virtual_levels_.size() - static_cast<std::size_t>(k)];
  return {L.points, L.hexas, L.stiffness, L.children};
}

VecNi<3> SparseGridTopology::finest_dims(VecNi<3> dims, int levels) {
  for (int i = 0; i < levels; ++i)
    for (int a = 0; a < 3; ++a) dims[a] = (dims[a] - 1) * 2 + 1;
  return dims;
}

bool SparseGridTopology::prepare(VecNi<3>& dims, std::vector<Vec3>& vertices,
                                 std::vector<std::vector<unsigned>>& facets) {
  build_failed_ = true;  // until the input is read
  types_.clear();
  stiffness_coefs_.clear();
  mass_coefs_.clear();
  children_.clear();
  virtual_levels_.clear();
  dims = n.get();
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 2) dims[a] = 2;
  n.set(dims);
  {
    // The finest grid has (n-1)·2^levels + 1 points per axis: check what it would allocate first.
    const int levels = std::min(std::max(nb_virtual_finer_levels.value(), 0), 60);
    double count = 1;
    for (int a = 0; a < 3; ++a) count *= (dims[a] - 1) * std::ldexp(1.0, levels) + 1;
    bool ok = check_allocation(*this, levels > 0 ? "n (with nbVirtualFinerLevels)" : "n",
                               parse::to_text(dims) +
                                   (levels > 0 ? ", nbVirtualFinerLevels = " + std::to_string(levels) : ""),
                               count, 256);
    if (ok && count > 2147483647.0) {
      msg_error("'n' = " + parse::to_text(dims) + " has more than 2³¹ points");
      ok = false;
    }
    if (!ok) return false;
  }

  if (nb_virtual_finer_levels.value() < 0) {
    msg_error("nbVirtualFinerLevels must be >= 0 (got " + std::to_string(nb_virtual_finer_levels.value()) + ")");
    return false;
  }
  const std::string& file = filename.value();
  auto ends_with = [&](const char* suffix) {
    const std::string s(suffix);
    return file.size() > s.size() && file.compare(file.size() - s.size(), s.size(), s) == 0;
  };
  if (ends_with(".raw") || ends_with(".voxel")) {
    msg_error("voxel files are not supported yet: '" + file + "'");
    return false;
  }
  vertices.clear();
  facets.clear();
  if (file.empty()) {
    vertices = position.get();
    if (vertices.empty()) {
      if (surface_optional()) {
        build_failed_ = false;
        return true;
      }
      msg_warning("no filename specified nor vertices given as parameters.");
      return false;
    }
    for (const Triangle& t : triangles_f.get()) facets.push_back({t[0], t[1], t[2]});
    for (const Quad& q : quads_f.get()) facets.push_back({q[0], q[1], q[2], q[3]});
  } else {
    std::string err;
    std::optional<io::MeshData> mesh;
    if (ends_with(".obj")) mesh = io::read_obj(file, &err);
    else if (ends_with(".msh")) mesh = io::read_gmsh(file, &err);
    else if (ends_with(".vtk") || ends_with(".vtu") || ends_with(".vtp")) mesh = io::read_vtk(file, &err);
    else err = "unsupported mesh format";
    if (!mesh) {
      msg_error("Loading mesh " + file + " failed: " + err);
      return false;
    }
    if (!mesh->face_positions.empty()) {
      // OBJ: the faces as written, indexing the raw vertex list.
      vertices = mesh->positions_definition.empty() ? mesh->positions : mesh->positions_definition;
      for (const auto& f : mesh->face_positions) {
        std::vector<unsigned> poly;
        for (int i : f)
          if (i >= 0) poly.push_back(static_cast<unsigned>(i));
        facets.push_back(std::move(poly));
      }
    } else {
      vertices = mesh->positions;
      for (const Triangle& t : mesh->triangles) facets.push_back({t[0], t[1], t[2]});
      for (const Quad& q : mesh->quads) facets.push_back({q[0], q[1], q[2], q[3]});
    }
    if (vertices.empty()) {
      msg_error("Loading mesh " + file + " failed: no vertex");
      return false;
    }
  }
  for (std::size_t f = 0; f < facets.size(); ++f)
    for (unsigned v : facets[f])
      if (v >= vertices.size()) {
        msg_error("facet " + std::to_string(f) + " uses vertex " + std::to_string(v) + " but the mesh has " +
                  std::to_string(vertices.size()) + " vertices");
        return false;
      }
  build_failed_ = false;
  return true;
}

void SparseGridTopology::adopt(Level&& level) {
  min.set(level.min);
  max.set(level.max);
  n.set(level.grid.n);
  grid_ = level.grid;
  types_ = std::move(level.types);
  stiffness_coefs_ = std::move(level.stiffness);
  mass_coefs_ = std::move(level.mass);
  sparse_of_regular_ = std::move(level.sparse_of_regular);
  children_ = std::move(level.children);
  position.set(std::move(level.points));
  hexahedra_f.set(std::move(level.hexas));
  set_nb_points(position.value().size());
}

bool SparseGridTopology::build_from_surface(Level& L, VecNi<3> dims, Vec3 lo_in, Vec3 hi_in, double width, bool only_inside,
                                            const std::vector<Vec3>& vertices,
                                            const std::vector<std::vector<unsigned>>& facets) const {
  // 1. Bounding box with a 1 % margin when min and max are both zero.
  if (lo_in == Vec3::Zero() && hi_in == Vec3::Zero()) {
    Vec3 lo = vertices[0], hi = vertices[0];
    for (std::size_t w = 1; w < vertices.size(); ++w)
      for (int a = 0; a < 3; ++a) {
        if (vertices[w][a] > hi[a]) hi[a] = vertices[w][a];
        else if (vertices[w][a] < lo[a]) lo[a] = vertices[w][a];
      }
    Vec3 diff = hi - lo;
    diff /= 100.0;
    lo_in = lo - diff;
    hi_in = hi + diff;
  }
  if (width != 0) {
    const Vec3 diff = hi_in - lo_in;
    dims = VecNi<3>(static_cast<int>(std::ceil(diff[0] / width)) + 1, static_cast<int>(std::ceil(diff[1] / width)) + 1,
                    static_cast<int>(std::ceil(diff[2] / width)) + 1);
  }
  // 2. The regular grid (SOFA's setSize + setPos).
  L.min = lo_in;
  L.max = hi_in;
  L.grid.set(dims, lo_in, hi_in);
  std::vector<CellType> type;
  if (!voxelize(L.grid, lo_in, hi_in, vertices, facets, type)) return false;
  build_from_types(L, type, only_inside);
  // 7. Boundary cells weigh half when fillWeighted.
  for (CellType t : L.types) {
    const float coef = t == CellType::boundary && fill_weighted.value() ? 0.5f : 1.0f;
    L.stiffness.push_back(coef);
    L.mass.push_back(coef);
  }
  return true;
}

bool SparseGridTopology::voxelize(const Grid& g, const Vec3& lo, const Vec3& hi, const std::vector<Vec3>& vertices,
                                  const std::vector<std::vector<unsigned>>& facets,
                                  std::vector<CellType>& type) const {
  const int nc = g.nb_cells();
  type.assign(static_cast<std::size_t>(nc), CellType::inside);
  auto cell_coord = [&](int c, int& x, int& y, int& z) {
    x = c % (g.n[0] - 1);
    c /= (g.n[0] - 1);
    y = c % (g.n[1] - 1);
    z = c / (g.n[1] - 1);
  };

  // 3. Cells holding a mesh vertex are boundary cells (vertices outside are pulled inside).
  const Vec3 delta = (g.dx + g.dy + g.dz) / 2;
  const double eps = std::numeric_limits<float>::epsilon();
  std::vector<int> vertex_cell(vertices.size(), -1);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    double x, y, z;
    int c = g.find(vertices[i], x, y, z);
    if (c >= 0) {
      type[static_cast<std::size_t>(c)] = CellType::boundary;
    } else {
      Vec3 v = vertices[i];
      for (int a = 0; a < 3; ++a) {
        if (v[a] - eps < lo[a]) v[a] = lo[a] + delta[a];
        else if (v[a] + eps > hi[a]) v[a] = hi[a] - delta[a];
      }
      c = g.find(v, x, y, z);
      if (c < 0) {
        msg_error("vertex " + std::to_string(i) + " not found in hexahedral topology");
        return false;
      }
    }
    vertex_cell[i] = c;
  }

  // 4. Cells crossed by a facet (fan-triangulated) are boundary cells.
  for (const auto& facet : facets) {
    for (std::size_t j = 2; j < facet.size(); ++j) {
      const int c0 = vertex_cell[facet[0]], c1 = vertex_cell[facet[j - 1]], c2 = vertex_cell[facet[j]];
      if (c0 == c1 && c0 == c2 && type[static_cast<std::size_t>(c0)] == CellType::boundary) continue;
      int i0[3], i1[3], i2[3];
      cell_coord(c0, i0[0], i0[1], i0[2]);
      cell_coord(c1, i1[0], i1[1], i1[2]);
      cell_coord(c2, i2[0], i2[1], i2[2]);
      int imin[3], imax[3];
      for (int a = 0; a < 3; ++a) {
        imin[a] = std::min(i0[a], std::min(i1[a], i2[a]));
        imax[a] = std::max(i0[a], std::max(i1[a], i2[a]));
      }
      const Vec3& A = vertices[facet[0]];
      const Vec3& B = vertices[facet[j - 1]];
      const Vec3& C = vertices[facet[j]];
      for (int x = imin[0]; x <= imax[0]; ++x)
        for (int y = imin[1]; y <= imax[1]; ++y)
          for (int z = imin[2]; z <= imax[2]; ++z) {
            const int c = g.cube(x, y, z);
            if (type[static_cast<std::size_t>(c)] == CellType::boundary) continue;
            const Vec3 corner0 = g.point(x, y, z);
            const Vec3 diagonal = g.point(x + 1, y + 1, z + 1) - corner0;
            const Vec3 centre = corner0 + diagonal * .5;
            float pts[3][3];
            for (int w = 0; w < 3; ++w) {
              pts[0][w] = static_cast<float>((A[w] - centre[w]) / diagonal[w]);
              pts[1][w] = static_cast<float>((B[w] - centre[w]) / diagonal[w]);
              pts[2][w] = static_cast<float>((C[w] - centre[w]) / diagonal[w]);
            }
            if (triangle_intersects_cube(pts)) type[static_cast<std::size_t>(c)] = CellType::boundary;
          }
    }
  }

  // 5. Flood fill from the border cells through non-boundary cells: those are outside.
  std::vector<char> tested(static_cast<std::size_t>(nc), 0);
  std::vector<std::array<int, 3>> stack;
  const int mx = g.n[0] - 2, my = g.n[1] - 2, mz = g.n[2] - 2;
  auto flood = [&](int sx, int sy, int sz) {
    stack.push_back({sx, sy, sz});
    while (!stack.empty()) {
      const auto [x, y, z] = stack.back();
      stack.pop_back();
      const auto c = static_cast<std::size_t>(g.cube(x, y, z));
      if (tested[c] || type[c] == CellType::boundary) continue;
      tested[c] = 1;
      type[c] = CellType::outside;
      if (x > 0) stack.push_back({x - 1, y, z});
      if (x < mx) stack.push_back({x + 1, y, z});
      if (y > 0) stack.push_back({x, y - 1, z});
      if (y < my) stack.push_back({x, y + 1, z});
      if (z > 0) stack.push_back({x, y, z - 1});
      if (z < mz) stack.push_back({x, y, z + 1});
    }
  };
  for (int y = 0; y <= my; ++y)
    for (int z = 0; z <= mz; ++z) flood(0, y, z), flood(mx, y, z);
  for (int x = 0; x <= mx; ++x)
    for (int z = 0; z <= mz; ++z) flood(x, 0, z), flood(x, my, z);
  for (int x = 0; x <= mx; ++x)
    for (int y = 0; y <= my; ++y) flood(x, y, 0), flood(x, y, mz);

  return true;
}

void SparseGridTopology::build_from_types(Level& L, const std::vector<CellType>& type, bool only_inside) {
  const Grid& g = L.grid;
  const int nc = g.nb_cells();
  // 6. Sparse cells: boundary cells first, then inside cells, in regular-cell order; points
  // are the distinct corners numbered in lexicographic order of their coordinates.
  L.types.clear();
  L.sparse_of_regular.assign(static_cast<std::size_t>(nc), -1);
  std::vector<int> cells;
  for (int c = 0; c < nc; ++c)
    if (type[static_cast<std::size_t>(c)] == CellType::boundary && !only_inside) {
      L.sparse_of_regular[static_cast<std::size_t>(c)] = static_cast<int>(cells.size());
      cells.push_back(c);
      L.types.push_back(CellType::boundary);
    }
  for (int c = 0; c < nc; ++c)
    if (type[static_cast<std::size_t>(c)] == CellType::inside) {
      L.sparse_of_regular[static_cast<std::size_t>(c)] = static_cast<int>(cells.size());
      cells.push_back(c);
      L.types.push_back(CellType::inside);
    }
  std::vector<std::array<int, 3>> coords(cells.size());
  for (std::size_t h = 0; h < cells.size(); ++h) {
    int c = cells[h];
    coords[h][0] = c % (g.n[0] - 1);
    c /= (g.n[0] - 1);
    coords[h][1] = c % (g.n[1] - 1);
    coords[h][2] = c / (g.n[1] - 1);
  }
  number_points(L, coords);
}

void SparseGridTopology::number_points(Level& L, const std::vector<std::array<int, 3>>& cells) {
  // Points are the distinct corners, numbered in lexicographic order of their coordinates.
  std::map<Vec3, unsigned, Lexicographic> index_of;
  std::vector<std::array<Vec3, 8>> corners(cells.size());
  for (std::size_t h = 0; h < cells.size(); ++h) {
    const auto& c = cells[h];
    for (int k = 0; k < 8; ++k) {
      corners[h][k] = L.grid.point(c[0] + kHexaCorner[k][0], c[1] + kHexaCorner[k][1], c[2] + kHexaCorner[k][2]);
      index_of[corners[h][k]] = 0;
    }
  }
  L.points.clear();
  unsigned counter = 0;
  for (auto& [p, idx] : index_of) {
    idx = counter++;
    L.points.push_back(p);
  }
  L.hexas.clear();
  for (const auto& cs : corners) {
    Hexa hx;
    for (int k = 0; k < 8; ++k) hx[k] = index_of[cs[k]];
    L.hexas.push_back(hx);
  }
}

void SparseGridTopology::coarsen(const Level& fine, Level& coarse) {
  // SOFA's buildFromFiner: each coarse cell groups 2×2×2 fine cells (x outer, then y, then z).
  const VecNi<3> fn = fine.grid.n;
  const VecNi<3> cn(fn[0] / 2 + 1, fn[1] / 2 + 1, fn[2] / 2 + 1);
  coarse.min = fine.min;
  Vec3 hi;
  hi[0] = coarse.min[0] + (cn[0] - 1) * 2.0 * fine.grid.dx[0];
  hi[1] = coarse.min[1] + (cn[1] - 1) * 2.0 * fine.grid.dy[1];
  hi[2] = coarse.min[2] + (cn[2] - 1) * 2.0 * fine.grid.dz[2];
  coarse.max = hi;
  coarse.grid.set(cn, coarse.min, coarse.max);
  coarse.sparse_of_regular.assign(static_cast<std::size_t>(coarse.grid.nb_cells()), -1);
  coarse.types.clear();
  coarse.children.clear();
  coarse.stiffness.clear();
  coarse.mass.clear();
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < cn[0] - 1; ++i)
    for (int j = 0; j < cn[1] - 1; ++j)
      for (int k = 0; k < cn[2] - 1; ++k) {
        int children[8];
        for (int idx = 0; idx < 8; ++idx) {
          const int x = 2 * i + (idx & 1), y = 2 * j + (idx & 2) / 2, z = 2 * k + (idx & 4) / 4;
          children[idx] = x < fn[0] - 1 && y < fn[1] - 1 && z < fn[2] - 1
                              ? fine.sparse_of_regular[static_cast<std::size_t>(fine.grid.cube(x, y, z))]
                              : -1;
        }
        bool inside = true, outside = true;
        for (int w = 0; w < 8 && (inside || outside); ++w) {
          if (children[w] < 0) {
            inside = false;
          } else if (fine.types[static_cast<std::size_t>(children[w])] == CellType::boundary) {
            inside = outside = false;
          } else if (fine.types[static_cast<std::size_t>(children[w])] == CellType::inside) {
            outside = false;
          }
        }
        if (outside) continue;
        coarse.types.push_back(inside ? CellType::inside : CellType::boundary);
        coarse.children.push_back({children[0], children[1], children[2], children[3], children[4], children[5],
                                   children[6], children[7]});
        coarse.sparse_of_regular[static_cast<std::size_t>(coarse.grid.cube(i, j, k))] = static_cast<int>(cells.size());
        cells.push_back({i, j, k});
        float stiffness = 0, mass = 0;
        for (int w = 0; w < 8; ++w)
          if (children[w] >= 0) {
            stiffness += fine.stiffness[static_cast<std::size_t>(children[w])];
            mass += fine.mass[static_cast<std::size_t>(children[w])];
          }
        stiffness /= 8.0;
        mass /= 8.0;
        coarse.stiffness.push_back(stiffness);
        coarse.mass.push_back(mass);
      }
  number_points(coarse, cells);
}

// ---------------------------------------------------------------- look-ups

unsigned SparseGridTopology::find_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  nb_points();
  double x, y, z;
  const int c = grid_.find(p, x, y, z);
  if (c < 0) return kInvalidIndex;
  fx = x - std::floor(x);
  fy = y - std::floor(y);
  fz = z - std::floor(z);
  const int s = sparse_of_regular_[static_cast<std::size_t>(c)];
  return s < 0 ? kInvalidIndex : static_cast<unsigned>(s);
}

unsigned SparseGridTopology::find_nearest_cube(const Vec3& p, double& fx, double& fy, double& fz) const {
  const std::vector<Hexa>& hexas = hexahedra();  // generates the grid first
  return nearest_boundary_cube(position.get(), hexas, types_, p, fx, fy, fz);
}

unsigned SparseGridTopology::nearest_boundary_cube(const std::vector<Vec3>& pts, const std::vector<Hexa>& hexas,
                                                   const std::vector<CellType>& types, const Vec3& p, double& fx,
                                                   double& fy, double& fz) {
  if (hexas.empty()) return kInvalidIndex;
  std::size_t best = 0;
  float best_len = 99999999.0f;
  // A ramified finest level has more hexahedra than types (SOFA keeps the unramified types).
  const std::size_t typed = std::min(hexas.size(), types.size());
  for (std::size_t w = 0; w < typed; ++w) {
    if (types[w] != CellType::boundary) continue;
    const Vec3 centre = (pts[hexas[w][0]] + pts[hexas[w][6]]) * .5;
    const float len = static_cast<float>((p - centre).norm());
    if (len < best_len) {
      best_len = len;
      best = w;
    }
  }
  const Vec3 p0 = pts[hexas[best][0]], p7 = pts[hexas[best][6]];
  const Vec3 rel = p - p0, diag = p7 - p0;
  fx = rel[0] / diag[0];
  fy = rel[1] / diag[1];
  fz = rel[2] / diag[2];
  return static_cast<unsigned>(best);
}

void register_sparse_grid_topology(Registry& r) {
  ComponentInfo info;
  info.name = "SparseGridTopology";
  info.category = "Topology";
  info.description = "Sparse grid in 3D: the cells of a regular grid inside or crossing a closed surface mesh";
  info.create = creator<SparseGridTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
