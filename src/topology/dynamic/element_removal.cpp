#include "topology/dynamic/element_removal.h"

#include <algorithm>
#include <string>

#include "topology/mesh_topology.h"

namespace sinew::topo {

namespace {

// Removes `id` from a shell keeping the order (SOFA: erase(remove(...))).
void erase_from(IndexList& shell, unsigned id) { shell.erase(std::remove(shell.begin(), shell.end(), id), shell.end()); }

void replace_in(IndexList& shell, unsigned from, unsigned to) { std::replace(shell.begin(), shell.end(), from, to); }

template <std::size_t N>
void replace_in(std::array<unsigned, N>& row, unsigned from, unsigned to) {
  for (unsigned& v : row)
    if (v == from) {
      v = to;
      return;  // SOFA replaces the first (only) occurrence
    }
}

// Moves the last entry of `v` into `slot` and pops it.
template <class T>
void swap_pop(std::vector<T>& v, std::size_t slot) {
  if (slot + 1 < v.size()) v[slot] = v.back();
  v.pop_back();
}

template <class T>
void shrink_by(std::vector<T>& v, std::size_t n) {
  v.resize(v.size() >= n ? v.size() - n : 0);
}

}  // namespace

Isolated remove_tetrahedra_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_items,
                                   bool isolated_points) {
  Isolated out;
  auto& tets = *m.tetrahedra;
  const bool want_points = isolated_items && isolated_points;
  const bool want_edges = isolated_items && !m.edges->empty();
  const bool want_triangles = isolated_items && !m.triangles->empty();
  for (unsigned id : decreasing) {
    const unsigned last = static_cast<unsigned>(tets.size() - 1);
    const Tetra t = tets[id];
    for (unsigned v : t) {
      IndexList& shell = m.tetrahedra_around_vertex[v];
      erase_from(shell, id);
      if (want_points && shell.empty()) out.points.push_back(v);
    }
    if (!m.edges_in_tetrahedron.empty())
      for (unsigned e : m.edges_in_tetrahedron[id]) {
        IndexList& shell = m.tetrahedra_around_edge[e];
        erase_from(shell, id);
        if (want_edges && shell.empty()) out.edges.push_back(e);
      }
    if (!m.triangles_in_tetrahedron.empty())
      for (unsigned f : m.triangles_in_tetrahedron[id]) {
        IndexList& shell = m.tetrahedra_around_triangle[f];
        erase_from(shell, id);
        if (want_triangles && shell.empty()) out.triangles.push_back(f);
      }
    if (id < last) {
      for (unsigned v : tets[last]) replace_in(m.tetrahedra_around_vertex[v], last, id);
      if (!m.edges_in_tetrahedron.empty())
        for (unsigned e : m.edges_in_tetrahedron[last]) replace_in(m.tetrahedra_around_edge[e], last, id);
      if (!m.triangles_in_tetrahedron.empty())
        for (unsigned f : m.triangles_in_tetrahedron[last]) replace_in(m.tetrahedra_around_triangle[f], last, id);
    }
    if (!m.triangles_in_tetrahedron.empty()) swap_pop(m.triangles_in_tetrahedron, id);
    if (!m.edges_in_tetrahedron.empty()) swap_pop(m.edges_in_tetrahedron, id);
    swap_pop(tets, id);
  }
  return out;
}

Isolated remove_triangles_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_edges,
                                  bool isolated_points) {
  Isolated out;
  auto& tris = *m.triangles;
  // Tetrahedron level: faces of tetrahedra that pointed at the moved triangle.
  if (!m.triangles_in_tetrahedron.empty()) {
    unsigned last = static_cast<unsigned>(m.tetrahedra_around_triangle.size() - 1);
    for (unsigned id : decreasing) {
      for (unsigned t : m.tetrahedra_around_triangle[last]) replace_in(m.triangles_in_tetrahedron[t], last, id);
      m.tetrahedra_around_triangle[id] = m.tetrahedra_around_triangle[last];
      --last;
    }
    shrink_by(m.tetrahedra_around_triangle, decreasing.size());
  }
  const bool want_edges = isolated_edges && !m.edges->empty();
  for (unsigned id : decreasing) {
    const unsigned last = static_cast<unsigned>(tris.size() - 1);
    for (unsigned v : tris[id]) {
      IndexList& shell = m.triangles_around_vertex[v];
      erase_from(shell, id);
      if (isolated_points && shell.empty()) out.points.push_back(v);
    }
    if (!m.edges_in_triangle.empty()) {
      for (unsigned e : m.edges_in_triangle[id]) {
        IndexList& shell = m.triangles_around_edge[e];
        erase_from(shell, id);
        if (want_edges && shell.empty()) out.edges.push_back(e);
      }
    }
    if (id < last) {
      for (unsigned v : tris[last]) replace_in(m.triangles_around_vertex[v], last, id);
      if (!m.edges_in_triangle.empty())
        for (unsigned e : m.edges_in_triangle[last]) replace_in(m.triangles_around_edge[e], last, id);
    }
    if (!m.edges_in_triangle.empty()) swap_pop(m.edges_in_triangle, id);
    swap_pop(tris, id);
  }
  return out;
}

namespace {

// Rows of `in` (element → sub-element) that named the moving last sub-element now name its new
// slot, and the "around" shells follow it (the upper-level half of SOFA's removeXProcess
// overrides, run before the sub-elements themselves are removed).
template <std::size_t N>
void renumber_sub_elements(std::vector<std::array<unsigned, N>>& in, std::vector<IndexList>& around,
                           std::size_t count, const std::vector<unsigned>& decreasing) {
  if (in.empty()) return;
  unsigned last = static_cast<unsigned>(count - 1);
  for (unsigned id : decreasing) {
    for (unsigned e : around[last]) replace_in(in[e], last, id);
    around[id] = around[last];
    --last;
  }
  shrink_by(around, decreasing.size());
}

}  // namespace

Isolated remove_hexahedra_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_items,
                                  bool isolated_points) {
  // SOFA's HexahedronSetTopologyModifier::removeHexahedraProcess: the same walk as tetrahedra.
  Isolated out;
  auto& hexas = *m.hexahedra;
  const bool want_points = isolated_items && isolated_points;
  const bool want_edges = isolated_items && !m.edges->empty();
  const bool want_quads = isolated_items && !m.quads->empty();
  const bool has_edges = !m.edges_in_hexahedron.empty(), has_quads = !m.quads_in_hexahedron.empty();
  for (unsigned id : decreasing) {
    const unsigned last = static_cast<unsigned>(hexas.size() - 1);
    for (unsigned v : hexas[id]) {
      IndexList& shell = m.hexahedra_around_vertex[v];
      erase_from(shell, id);
      if (want_points && shell.empty()) out.points.push_back(v);
    }
    if (has_edges)
      for (unsigned e : m.edges_in_hexahedron[id]) {
        IndexList& shell = m.hexahedra_around_edge[e];
        erase_from(shell, id);
        if (want_edges && shell.empty()) out.edges.push_back(e);
      }
    if (has_quads)
      for (unsigned q : m.quads_in_hexahedron[id]) {
        IndexList& shell = m.hexahedra_around_quad[q];
        erase_from(shell, id);
        if (want_quads && shell.empty()) out.quads.push_back(q);
      }
    if (id < last) {
      for (unsigned v : hexas[last]) replace_in(m.hexahedra_around_vertex[v], last, id);
      if (has_edges)
        for (unsigned e : m.edges_in_hexahedron[last]) replace_in(m.hexahedra_around_edge[e], last, id);
      if (has_quads)
        for (unsigned q : m.quads_in_hexahedron[last]) replace_in(m.hexahedra_around_quad[q], last, id);
    }
    if (has_quads) swap_pop(m.quads_in_hexahedron, id);
    if (has_edges) swap_pop(m.edges_in_hexahedron, id);
    swap_pop(hexas, id);
  }
  return out;
}

Isolated remove_quads_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_edges,
                              bool isolated_points) {
  Isolated out;
  auto& quads = *m.quads;
  // Hexahedron level first: faces of hexahedra that pointed at the moved quad.
  renumber_sub_elements(m.quads_in_hexahedron, m.hexahedra_around_quad, m.hexahedra_around_quad.size(), decreasing);
  const bool want_edges = isolated_edges && !m.edges->empty();
  const bool has_edges = !m.edges_in_quad.empty();
  for (unsigned id : decreasing) {
    const unsigned last = static_cast<unsigned>(quads.size() - 1);
    for (unsigned v : quads[id]) {
      IndexList& shell = m.quads_around_vertex[v];
      erase_from(shell, id);
      if (isolated_points && shell.empty()) out.points.push_back(v);
    }
    if (has_edges)
      for (unsigned e : m.edges_in_quad[id]) {
        IndexList& shell = m.quads_around_edge[e];
        erase_from(shell, id);
        if (want_edges && shell.empty()) out.edges.push_back(e);
      }
    if (id < last) {
      for (unsigned v : quads[last]) replace_in(m.quads_around_vertex[v], last, id);
      if (has_edges)
        for (unsigned e : m.edges_in_quad[last]) replace_in(m.quads_around_edge[e], last, id);
    }
    if (has_edges) swap_pop(m.edges_in_quad, id);
    swap_pop(quads, id);
  }
  return out;
}

Isolated remove_edges_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_points) {
  Isolated out;
  // Tetrahedron then triangle level: element rows that pointed at the moved edge.
  if (!m.edges_in_tetrahedron.empty()) {
    unsigned last = static_cast<unsigned>(m.edges->size() - 1);
    for (unsigned id : decreasing) {
      for (unsigned t : m.tetrahedra_around_edge[last]) replace_in(m.edges_in_tetrahedron[t], last, id);
      m.tetrahedra_around_edge[id] = m.tetrahedra_around_edge[last];
      --last;
    }
    shrink_by(m.tetrahedra_around_edge, decreasing.size());
  }
  if (!m.edges_in_triangle.empty()) {
    unsigned last = static_cast<unsigned>(m.edges->size() - 1);
    for (unsigned id : decreasing) {
      for (unsigned t : m.triangles_around_edge[last]) replace_in(m.edges_in_triangle[t], last, id);
      m.triangles_around_edge[id] = m.triangles_around_edge[last];
      --last;
    }
    shrink_by(m.triangles_around_edge, decreasing.size());
  }
  // Hexahedron then quad level (SOFA's Hexahedron/QuadSetTopologyModifier::removeEdgesProcess).
  renumber_sub_elements(m.edges_in_hexahedron, m.hexahedra_around_edge, m.edges->size(), decreasing);
  renumber_sub_elements(m.edges_in_quad, m.quads_around_edge, m.edges->size(), decreasing);
  auto& edges = *m.edges;
  for (unsigned id : decreasing) {
    const unsigned last = static_cast<unsigned>(edges.size() - 1);
    const Edge e = edges[id];
    for (unsigned v : e) {
      IndexList& shell = m.edges_around_vertex[v];
      erase_from(shell, id);
      if (isolated_points && shell.empty()) out.points.push_back(v);
    }
    if (id < last)
      for (unsigned v : edges[last]) replace_in(m.edges_around_vertex[v], last, id);
    swap_pop(edges, id);
  }
  return out;
}

void remove_points_process(DynamicMesh& m, const std::vector<unsigned>& decreasing) {
  // Tetrahedra, triangles, edges in turn (SOFA's modifier chain; hexahedra and quads before the
  // edges in the other family), each with its vertex shells.
  auto renumber = [&](auto& elements, std::vector<IndexList>& shells) {
    if (elements.empty() && shells.empty()) return;
    unsigned last = m.nb_points - 1;
    for (unsigned id : decreasing) {
      for (unsigned e : shells[last]) replace_in(elements[e], last, id);
      shells[id] = shells[last];
      --last;
    }
    shrink_by(shells, decreasing.size());
  };
  renumber(*m.tetrahedra, m.tetrahedra_around_vertex);
  renumber(*m.triangles, m.triangles_around_vertex);
  renumber(*m.hexahedra, m.hexahedra_around_vertex);
  renumber(*m.quads, m.quads_around_vertex);
  renumber(*m.edges, m.edges_around_vertex);
  m.nb_points = decreasing.size() < m.nb_points ? m.nb_points - static_cast<unsigned>(decreasing.size()) : 0;
}

// ---------------------------------------------------------------- consistency

namespace {
template <class List>
std::string check_shells(const char* what, const List& elements, const std::vector<IndexList>& shells,
                         std::size_t nb_points) {
  if (elements.empty()) return {};
  if (shells.size() != nb_points)
    return std::string(what) + " around vertex: " + std::to_string(shells.size()) + " shells for " +
           std::to_string(nb_points) + " points";
  std::size_t listed = 0;
  for (std::size_t v = 0; v < shells.size(); ++v)
    for (unsigned e : shells[v]) {
      ++listed;
      if (e >= elements.size() || std::find(elements[e].begin(), elements[e].end(), v) == elements[e].end())
        return std::string(what) + " " + std::to_string(e) + " listed around vertex " + std::to_string(v) +
               " does not use it";
    }
  std::size_t uses = 0;
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (unsigned v : elements[e]) {
      ++uses;
      if (v >= nb_points)
        return std::string(what) + " " + std::to_string(e) + " uses point " + std::to_string(v) + " of " +
               std::to_string(nb_points);
    }
  if (uses != listed) return std::string(what) + ": shells and elements disagree";
  return {};
}

template <std::size_t N>
std::string check_in(const char* what, const std::vector<std::array<unsigned, N>>& rows, std::size_t n_elements,
                     const std::vector<IndexList>& around, std::size_t n_sub) {
  if (rows.empty()) return {};
  if (rows.size() != n_elements || around.size() != n_sub) return std::string(what) + ": table sizes disagree";
  for (std::size_t e = 0; e < rows.size(); ++e)
    for (unsigned s : rows[e])
      if (s >= n_sub || std::count(around[s].begin(), around[s].end(), e) != 1)
        return std::string(what) + ": element " + std::to_string(e) + " and sub-element " + std::to_string(s) +
               " disagree";
  return {};
}
}  // namespace

std::string check_dynamic_mesh(const DynamicMesh& m) {
  std::string r;
  if (!(r = check_shells("tetrahedron", *m.tetrahedra, m.tetrahedra_around_vertex, m.nb_points)).empty()) return r;
  if (!(r = check_shells("triangle", *m.triangles, m.triangles_around_vertex, m.nb_points)).empty()) return r;
  if (!(r = check_shells("edge", *m.edges, m.edges_around_vertex, m.nb_points)).empty()) return r;
  if (!(r = check_in("edges in triangle", m.edges_in_triangle, m.triangles->size(), m.triangles_around_edge,
                     m.edges->size())).empty())
    return r;
  if (!(r = check_in("edges in tetrahedron", m.edges_in_tetrahedron, m.tetrahedra->size(), m.tetrahedra_around_edge,
                     m.edges->size())).empty())
    return r;
  if (!(r = check_in("triangles in tetrahedron", m.triangles_in_tetrahedron, m.tetrahedra->size(),
                     m.tetrahedra_around_triangle, m.triangles->size())).empty())
    return r;
  // The element-in-element tables must name the sub-elements with the element's vertices.
  for (std::size_t t = 0; t < m.edges_in_triangle.size(); ++t)
    for (unsigned j = 0; j < 3; ++j) {
      const Edge& e = (*m.edges)[m.edges_in_triangle[t][j]];
      const Triangle& tr = (*m.triangles)[t];
      const unsigned a = tr[(j + 1) % 3], b = tr[(j + 2) % 3];
      if (!((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)))
        return "edge " + std::to_string(j) + " of triangle " + std::to_string(t) + " has other vertices";
    }
  for (std::size_t t = 0; t < m.edges_in_tetrahedron.size(); ++t)
    for (unsigned j = 0; j < 6; ++j) {
      const Edge& e = (*m.edges)[m.edges_in_tetrahedron[t][j]];
      const Tetra& te = (*m.tetrahedra)[t];
      const unsigned a = te[kEdgesInTetra[j][0]], b = te[kEdgesInTetra[j][1]];
      if (!((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)))
        return "edge " + std::to_string(j) + " of tetrahedron " + std::to_string(t) + " has other vertices";
    }
  for (std::size_t t = 0; t < m.triangles_in_tetrahedron.size(); ++t)
    for (unsigned j = 0; j < 4; ++j) {
      Triangle f = (*m.triangles)[m.triangles_in_tetrahedron[t][j]];
      const Tetra& te = (*m.tetrahedra)[t];
      std::array<unsigned, 3> want{te[(j + 1) % 4], te[(j + 2) % 4], te[(j + 3) % 4]};
      std::sort(f.begin(), f.end());
      std::sort(want.begin(), want.end());
      if (f != want) return "face " + std::to_string(j) + " of tetrahedron " + std::to_string(t) + " has other vertices";
    }
  return {};
}

}  // namespace sinew::topo
