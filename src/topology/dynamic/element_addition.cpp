#include "topology/dynamic/element_addition.h"

namespace sinew::topo {

namespace {
// A point named beyond the count makes it grow (SOFA does the same rather than refusing).
void grow_points(DynamicMesh& m, unsigned v) {
  if (v + 1 > m.nb_points) m.nb_points = v + 1;
}
void fit(std::vector<IndexList>& shells, std::size_t n) {
  if (shells.size() < n) shells.resize(n);
}
}  // namespace

unsigned find_edge(const DynamicMesh& m, unsigned a, unsigned b) {
  if (a >= m.edges_around_vertex.size()) return kNoIndex;
  for (unsigned e : m.edges_around_vertex[a]) {
    const Edge& E = (*m.edges)[e];
    if ((E[0] == a && E[1] == b) || (E[0] == b && E[1] == a)) return e;
  }
  return kNoIndex;
}

unsigned find_triangle(const DynamicMesh& m, unsigned a, unsigned b, unsigned c) {
  if (a >= m.triangles_around_vertex.size()) return kNoIndex;
  unsigned found = kNoIndex;
  for (unsigned id : m.triangles_around_vertex[a]) {
    const Triangle& T = (*m.triangles)[id];
    auto has = [&](unsigned v) { return T[0] == v || T[1] == v || T[2] == v; };
    if (!has(b) || !has(c)) continue;
    if (found != kNoIndex) return kNoIndex;  // more than one: SOFA answers none
    found = id;
  }
  return found;
}

void add_points_process(DynamicMesh& m, unsigned n) {
  m.nb_points += n;
  if (!m.edges->empty() || !m.edges_around_vertex.empty()) fit(m.edges_around_vertex, m.nb_points);
  if (!m.triangles->empty() || !m.triangles_around_vertex.empty()) fit(m.triangles_around_vertex, m.nb_points);
  if (!m.tetrahedra->empty() || !m.tetrahedra_around_vertex.empty()) fit(m.tetrahedra_around_vertex, m.nb_points);
}

void add_edge_process(DynamicMesh& m, const Edge& e) {
  const unsigned id = static_cast<unsigned>(m.edges->size());
  grow_points(m, e[0]);
  grow_points(m, e[1]);
  fit(m.edges_around_vertex, m.nb_points);
  m.edges_around_vertex[e[0]].push_back(id);
  m.edges_around_vertex[e[1]].push_back(id);
  m.edges->push_back(e);
  // Higher levels keep one (empty for now) shell per edge.
  if (!m.triangles->empty() || !m.triangles_around_edge.empty()) fit(m.triangles_around_edge, m.edges->size());
  if (!m.tetrahedra->empty() || !m.tetrahedra_around_edge.empty()) fit(m.tetrahedra_around_edge, m.edges->size());
  if (!m.quads->empty() || !m.quads_around_edge.empty()) fit(m.quads_around_edge, m.edges->size());
  if (!m.hexahedra->empty() || !m.hexahedra_around_edge.empty()) fit(m.hexahedra_around_edge, m.edges->size());
}

std::vector<unsigned> add_triangle_process(DynamicMesh& m, const Triangle& t) {
  std::vector<unsigned> created;
  const unsigned id = static_cast<unsigned>(m.triangles->size());
  for (unsigned v : t) grow_points(m, v);
  fit(m.triangles_around_vertex, m.nb_points);
  if (!m.edges_around_vertex.empty()) fit(m.edges_around_vertex, m.nb_points);
  for (unsigned v : t) m.triangles_around_vertex[v].push_back(id);
  if (m.edges_in_triangle.size() < id + 1u) m.edges_in_triangle.resize(id + 1u);
  for (unsigned j = 0; j < 3; ++j) {
    const unsigned a = t[(j + 1) % 3], b = t[(j + 2) % 3];
    unsigned e = find_edge(m, a, b);
    if (e == kNoIndex) {
      add_edge_process(m, Edge{a, b});
      e = static_cast<unsigned>(m.edges->size() - 1);
      created.push_back(e);
    }
    m.edges_in_triangle[id][j] = e;
    fit(m.triangles_around_edge, m.edges->size());
    m.triangles_around_edge[e].push_back(id);
  }
  m.triangles->push_back(t);
  return created;
}

std::vector<Created> add_tetrahedron_process(DynamicMesh& m, const Tetra& t) {
  std::vector<Created> created;
  const unsigned id = static_cast<unsigned>(m.tetrahedra->size());
  for (unsigned v : t) grow_points(m, v);
  fit(m.tetrahedra_around_vertex, m.nb_points);
  for (unsigned v : t) m.tetrahedra_around_vertex[v].push_back(id);

  if (m.triangles_in_tetrahedron.size() < id + 1u) m.triangles_in_tetrahedron.resize(id + 1u);
  for (unsigned j = 0; j < 4; ++j) {
    const Triangle face{t[kTrianglesInTetra[j][0]], t[kTrianglesInTetra[j][1]], t[kTrianglesInTetra[j][2]]};
    unsigned f = find_triangle(m, face[0], face[1], face[2]);
    if (f == kNoIndex) {
      for (unsigned e : add_triangle_process(m, face)) created.push_back({Created::Kind::edge, e});
      f = static_cast<unsigned>(m.triangles->size() - 1);
      created.push_back({Created::Kind::triangle, f});
    }
    m.triangles_in_tetrahedron[id][j] = f;
    fit(m.tetrahedra_around_triangle, m.triangles->size());
    m.tetrahedra_around_triangle[f].push_back(id);
  }

  if (m.edges_in_tetrahedron.size() < id + 1u) m.edges_in_tetrahedron.resize(id + 1u);
  for (unsigned j = 0; j < 6; ++j) {
    const unsigned a = t[kEdgesInTetra[j][0]], b = t[kEdgesInTetra[j][1]];
    unsigned e = find_edge(m, a, b);
    if (e == kNoIndex) {  // only when the faces did not bring it (never with the faces above)
      add_edge_process(m, Edge{a, b});
      e = static_cast<unsigned>(m.edges->size() - 1);
      created.push_back({Created::Kind::edge, e});
    }
    m.edges_in_tetrahedron[id][j] = e;
    fit(m.tetrahedra_around_edge, m.edges->size());
    m.tetrahedra_around_edge[e].push_back(id);
  }
  m.tetrahedra->push_back(t);
  return created;
}

unsigned find_quad(const DynamicMesh& m, unsigned a, unsigned b, unsigned c, unsigned d) {
  if (a >= m.quads_around_vertex.size()) return kNoIndex;
  unsigned found = kNoIndex;
  for (unsigned id : m.quads_around_vertex[a]) {
    const Quad& Q = (*m.quads)[id];
    auto has = [&](unsigned v) { return Q[0] == v || Q[1] == v || Q[2] == v || Q[3] == v; };
    if (!has(b) || !has(c) || !has(d)) continue;
    if (found != kNoIndex) return kNoIndex;  // more than one: SOFA answers none
    found = id;
  }
  return found;
}

std::vector<unsigned> add_quad_process(DynamicMesh& m, const Quad& q) {
  std::vector<unsigned> created;
  const unsigned id = static_cast<unsigned>(m.quads->size());
  for (unsigned v : q) grow_points(m, v);
  fit(m.quads_around_vertex, m.nb_points);
  if (!m.edges_around_vertex.empty()) fit(m.edges_around_vertex, m.nb_points);
  for (unsigned v : q) m.quads_around_vertex[v].push_back(id);
  if (m.edges_in_quad.size() < id + 1u) m.edges_in_quad.resize(id + 1u);
  for (unsigned j = 0; j < 4; ++j) {
    const unsigned a = q[(j + 1) % 4], b = q[(j + 2) % 4];
    unsigned e = find_edge(m, a, b);
    if (e == kNoIndex) {
      add_edge_process(m, Edge{a, b});
      e = static_cast<unsigned>(m.edges->size() - 1);
      created.push_back(e);
    }
    m.edges_in_quad[id][j] = e;
    fit(m.quads_around_edge, m.edges->size());
    m.quads_around_edge[e].push_back(id);
  }
  m.quads->push_back(q);
  return created;
}

std::vector<Created> add_hexahedron_process(DynamicMesh& m, const Hexa& h) {
  std::vector<Created> created;
  const unsigned id = static_cast<unsigned>(m.hexahedra->size());
  for (unsigned v : h) grow_points(m, v);
  fit(m.hexahedra_around_vertex, m.nb_points);
  for (unsigned v : h) m.hexahedra_around_vertex[v].push_back(id);

  if (m.quads_in_hexahedron.size() < id + 1u) m.quads_in_hexahedron.resize(id + 1u);
  for (unsigned j = 0; j < 6; ++j) {
    const auto& f = kQuadsInHexa[j];
    const Quad face{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
    unsigned q = find_quad(m, face[0], face[1], face[2], face[3]);
    if (q == kNoIndex) {
      for (unsigned e : add_quad_process(m, face)) created.push_back({Created::Kind::edge, e});
      q = static_cast<unsigned>(m.quads->size() - 1);
      created.push_back({Created::Kind::quad, q});
    }
    m.quads_in_hexahedron[id][j] = q;
    fit(m.hexahedra_around_quad, m.quads->size());
    m.hexahedra_around_quad[q].push_back(id);
  }

  if (m.edges_in_hexahedron.size() < id + 1u) m.edges_in_hexahedron.resize(id + 1u);
  for (unsigned j = 0; j < 12; ++j) {
    const unsigned a = h[kEdgesInHexa[j][0]], b = h[kEdgesInHexa[j][1]];
    unsigned e = find_edge(m, a, b);
    if (e == kNoIndex) {  // only when the faces did not bring it (never with the faces above)
      add_edge_process(m, Edge{a, b});
      e = static_cast<unsigned>(m.edges->size() - 1);
      created.push_back({Created::Kind::edge, e});
    }
    m.edges_in_hexahedron[id][j] = e;
    fit(m.hexahedra_around_edge, m.edges->size());
    m.hexahedra_around_edge[e].push_back(id);
  }
  m.hexahedra->push_back(h);
  return created;
}

}  // namespace sinew::topo
