#include "io/vtk_common.h"

#include <algorithm>
#include <set>
#include <strings.h>

#include "io/reader_text.h"

namespace sinew::io::internal {

int vtk_type_size(const std::string& t, bool* is_float, bool* is_signed) {
  auto eq = [&](const char* a, const char* b) { return strcasecmp(t.c_str(), a) == 0 || strcasecmp(t.c_str(), b) == 0; };
  *is_float = false;
  *is_signed = true;
  if (eq("char", "Int8")) return 1;
  if (eq("unsigned_char", "UInt8")) return *is_signed = false, 1;
  if (eq("short", "Int16")) return 2;
  if (eq("unsigned_short", "UInt16")) return *is_signed = false, 2;
  if (eq("int", "Int32")) return 4;
  if (eq("unsigned_int", "UInt32")) return *is_signed = false, 4;
  if (eq("long", "Int64")) return 8;
  if (eq("unsigned_long", "UInt64")) return *is_signed = false, 8;
  if (eq("float", "Float32")) return *is_float = true, 4;
  if (eq("double", "Float64")) return *is_float = true, 8;
  return 0;
}

bool vtk_to_mesh(MeshData& m, const VtkCells& vc, const std::string& path, std::string* error, bool flip) {
  const std::size_t np = m.positions.size();
  auto idx = [&](double d) { return static_cast<unsigned>(static_cast<long long>(d)); };
  auto check = [&](unsigned i) { return i < np; };
  if (vc.has_polygons) {
    const auto& p = vc.polygons;
    std::size_t i = 0;
    int poly = 0;
    while (i < p.size()) {
      if (p[i] < 0) return fail(error, path + ": polygon " + std::to_string(poly) + " has a negative size");
      const auto nv = static_cast<std::size_t>(p[i]);
      ++i;
      if (i + nv > p.size()) return fail(error, path + ": polygon " + std::to_string(poly) + " is truncated");
      for (std::size_t j = 0; j < nv; ++j)
        if (!check(idx(p[i + j])))
          return fail(error, path + ": invalid point " + std::to_string(idx(p[i + j])) + " in polygon " +
                                 std::to_string(poly));
      if (nv == 4) {
        m.quads.push_back(maybe_flip(Quad{idx(p[i]), idx(p[i + 1]), idx(p[i + 2]), idx(p[i + 3])}, flip));
      } else if (nv >= 3) {
        unsigned f0 = idx(p[i]), f1 = idx(p[i + 1]);
        for (std::size_t j = 2; j < nv; ++j) {
          const unsigned f2 = idx(p[i + j]);
          m.triangles.push_back(maybe_flip(Triangle{f0, f1, f2}, flip));
          f1 = f2;
        }
      }
      i += nv;
      ++poly;
    }
    return true;
  }
  if (!(vc.has_cells && vc.has_types)) return true;
  static const unsigned tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  static const unsigned tet_edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  std::set<Edge> edge_set;
  const auto& c = vc.cells;
  std::size_t i = 0;
  for (std::size_t cell = 0; cell < vc.number_of_cells; ++cell) {
    if (cell >= vc.types.size()) return fail(error, path + ": fewer cell types than cells");
    const int t = static_cast<int>(vc.types[cell]);
    std::size_t nv = 0;
    if (!vc.offsets.empty()) {
      const double b0 = cell == 0 ? 0.0 : vc.offsets[cell - 1], e0 = vc.offsets[cell];
      if (b0 < 0 || e0 < 0 || e0 > static_cast<double>(c.size()))
        return fail(error, path + ": cell " + std::to_string(cell) + " has invalid offsets");
      i = static_cast<std::size_t>(b0);
      const std::size_t end = static_cast<std::size_t>(e0);
      nv = end >= i ? end - i : 0;
    } else {
      if (i >= c.size()) return fail(error, path + ": cell " + std::to_string(cell) + " is missing");
      if (c[i] < 0) return fail(error, path + ": cell " + std::to_string(cell) + " has a negative size");
      nv = static_cast<std::size_t>(c[i]);
      ++i;
    }
    if (i + nv > c.size()) return fail(error, path + ": cell " + std::to_string(cell) + " is truncated");
    std::vector<unsigned> v(nv);
    for (std::size_t k = 0; k < nv; ++k) {
      v[k] = idx(c[i + k]);
      if (!check(v[k]))
        return fail(error, path + ": cell " + std::to_string(cell) + " uses point " + std::to_string(v[k]) +
                               " but the file has " + std::to_string(np) + " points");
    }
    auto need = [&](std::size_t k) {
      if (nv < k)
        return fail(error, path + ": cell " + std::to_string(cell) + " of type " + std::to_string(t) + " has " +
                               std::to_string(nv) + " points");
      return true;
    };
    auto quad_edges = [&](const unsigned (*pairs)[2], int count, int mid0) {
      for (int j = 0; j < count; ++j) {
        const unsigned a = std::min(v[pairs[j][0]], v[pairs[j][1]]), b = std::max(v[pairs[j][0]], v[pairs[j][1]]);
        if (edge_set.insert({a, b}).second) {
          m.edges.push_back({a, b});
          m.high_order_edge_positions.push_back({v[mid0 + j], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
        }
      }
    };
    switch (t) {
      case 0:
      case 1:
      case 2: break;
      case 3:
        if (!need(2)) return false;
        m.edges.push_back({v[0], v[1]});
        break;
      case 4: m.polylines.push_back(v); break;
      case 5:
        if (!need(3)) return false;
        m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, flip));
        break;
      case 6:
        for (std::size_t j = 0; j + 2 < nv; ++j)
          m.triangles.push_back(maybe_flip(
              (j & 1) ? Triangle{v[j], v[j + 1], v[j + 2]} : Triangle{v[j], v[j + 2], v[j + 1]}, flip));
        break;
      case 7:
        for (std::size_t j = 2; j < nv; ++j) m.triangles.push_back(maybe_flip(Triangle{v[0], v[j - 1], v[j]}, flip));
        break;
      case 8:
        if (!need(4)) return false;
        m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[3], v[2]}, flip));
        break;
      case 9:
        if (!need(4)) return false;
        m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[2], v[3]}, flip));
        break;
      case 10:
        if (!need(4)) return false;
        m.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
        break;
      case 11:
        if (!need(8)) return false;
        m.hexahedra.push_back({v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6]});
        break;
      case 12:
        if (!need(8)) return false;
        m.hexahedra.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]});
        break;
      case 13:
        if (!need(6)) return false;
        m.prisms.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
        break;
      case 14:
        if (!need(5)) return false;
        m.pyramids.push_back({v[0], v[1], v[2], v[3], v[4]});
        break;
      case 21:
        if (!need(3)) return false;
        m.edges.push_back({v[0], v[1]});
        m.high_order_edge_positions.push_back({v[2], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
        break;
      case 22:
        if (!need(6)) return false;
        m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, flip));
        quad_edges(tri_edges, 3, 3);
        break;
      case 24:
        if (!need(10)) return false;
        m.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
        quad_edges(tet_edges, 6, 4);
        break;
      default: return fail(error, path + ": unsupported VTK cell type " + std::to_string(t));
    }
    if (vc.offsets.empty()) i += nv;
  }
  return true;
}

bool set_points(MeshData& m, const std::vector<double>& xyz, const std::string& path, std::string* error) {
  m.positions.resize(xyz.size() / 3);
  for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  std::size_t bad = 0;
  if (all_finite(m.positions, &bad)) return true;
  return fail(error, path + ": point " + std::to_string(bad) + " has a non-finite coordinate");
}

}  // namespace sinew::io::internal
