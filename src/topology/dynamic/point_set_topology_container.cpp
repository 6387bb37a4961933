#include "topology/dynamic/point_set_topology_container.h"

#include <algorithm>

#include "core/registry.h"
#include "topology/dynamic/element_addition.h"

namespace sinew {

PointSetTopologyContainer::PointSetTopologyContainer() = default;

namespace {
std::size_t main_list_points(const PointSetTopologyContainer& c) {
  using L = PointSetTopologyContainer::Level;
  switch (c.level()) {
    case L::point: return 0;
    case L::edge: return topo::count_points(c.edges_f.get());
    case L::triangle: return topo::count_points(c.triangles_f.get());
    case L::quad: return topo::count_points(c.quads_f.get());
    case L::tetrahedron: return topo::count_points(c.tetrahedra_f.get());
    case L::hexahedron: return topo::count_points(c.hexahedra_f.get());
  }
  return 0;
}

bool main_list_empty(const PointSetTopologyContainer& c) {
  using L = PointSetTopologyContainer::Level;
  switch (c.level()) {
    case L::point: return true;
    case L::edge: return c.edges_f.get().empty();
    case L::triangle: return c.triangles_f.get().empty();
    case L::quad: return c.quads_f.get().empty();
    case L::tetrahedron: return c.tetrahedra_f.get().empty();
    case L::hexahedron: return c.hexahedra_f.get().empty();
  }
  return true;
}
}  // namespace

std::size_t PointSetTopologyContainer::nb_points() const {
  if (initialised_) return nb_points_f.value();
  // Before init (a state initialised earlier in the node asks): what init will compute.
  const std::size_t np = position.get().size();
  if (level() == Level::point || position.is_set()) return std::max<std::size_t>(np, nb_points_f.value());
  return std::max<std::size_t>(main_list_points(*this), nb_points_f.value());
}

void PointSetTopologyContainer::set_nb_points(std::size_t n) { nb_points_f.set(static_cast<unsigned>(n)); }

void PointSetTopologyContainer::clear_topology() {
  MeshContainer::clear_topology();
  nb_points_f.set(0);
  mesh_.reset();
}

void PointSetTopologyContainer::init() {
  MeshContainer::init();
  const std::size_t np = position.get().size();
  if (level() == Level::point) {
    if (np > nb_points_f.value()) nb_points_f.set(static_cast<unsigned>(np));
  } else if (position.is_set() && !(np == 0 && nb_points_f.value() > 0)) {
    // Deviation: an empty `position` with a point count already given (a topological mapping
    // called clear() then setNbPoints()) keeps that count. SOFA's clear() marks `position` as
    // set and the container ends with 0 points (warning while building its buffers); the
    // element lists are the same either way.
    nb_points_f.set(static_cast<unsigned>(np));
  } else {
    const std::size_t n = main_list_points(*this);
    if (n > nb_points_f.value()) nb_points_f.set(static_cast<unsigned>(n));
  }
  initialised_ = true;
  if (!main_list_empty(*this)) create_lower_lists();
  // Element indices beyond the point count make the neighbourhood buffers inconsistent (SOFA warns).
  if (nb_points_f.value() > 0) check_indices(nb_points_f.value());
}

// ---------------------------------------------------------------- removal view

bool PointSetTopologyContainer::live() const {
  if (!mesh_) return false;
  edges();
  triangles();
  tetrahedra();
  quads();
  hexahedra();
  const std::uint64_t v[6] = {edges_f.version(),     triangles_f.version(), tetrahedra_f.version(),
                              nb_points_f.version(), quads_f.version(),     hexahedra_f.version()};
  return std::equal(v, v + 6, mesh_versions_);
}

topo::DynamicMesh& PointSetTopologyContainer::begin_edit() {
  if (!live()) {
    auto m = std::make_unique<topo::DynamicMesh>();
    m->nb_points = static_cast<unsigned>(nb_points());
    // Copies of the cached arrays (built now if needed), for the kinds the container holds.
    if (!edges().empty()) m->edges_around_vertex = MeshContainer::edges_around_vertex();
    if (!triangles().empty()) {
      m->triangles_around_vertex = MeshContainer::triangles_around_vertex();
      if (!edges().empty()) {
        m->edges_in_triangle = MeshContainer::edges_in_triangle();
        m->triangles_around_edge = MeshContainer::triangles_around_edge();
      }
    }
    if (!tetrahedra().empty()) {
      m->tetrahedra_around_vertex = MeshContainer::tetrahedra_around_vertex();
      if (!edges().empty()) {
        m->edges_in_tetrahedron = MeshContainer::edges_in_tetrahedron();
        m->tetrahedra_around_edge = MeshContainer::tetrahedra_around_edge();
      }
      if (!triangles().empty()) {
        m->triangles_in_tetrahedron = MeshContainer::triangles_in_tetrahedron();
        m->tetrahedra_around_triangle = MeshContainer::tetrahedra_around_triangle();
      }
    }
    if (!quads().empty()) {
      m->quads_around_vertex = MeshContainer::quads_around_vertex();
      if (!edges().empty()) {
        m->edges_in_quad = MeshContainer::edges_in_quad();
        m->quads_around_edge = MeshContainer::quads_around_edge();
      }
    }
    if (!hexahedra().empty()) {
      m->hexahedra_around_vertex = MeshContainer::hexahedra_around_vertex();
      if (!edges().empty()) {
        m->edges_in_hexahedron = MeshContainer::edges_in_hexahedron();
        m->hexahedra_around_edge = MeshContainer::hexahedra_around_edge();
      }
      if (!quads().empty()) {
        m->quads_in_hexahedron = MeshContainer::quads_in_hexahedron();
        m->hexahedra_around_quad = MeshContainer::hexahedra_around_quad();
      }
    }
    // Vertex shells span every point, isolated ones included.
    for (auto* shells : {&m->edges_around_vertex, &m->triangles_around_vertex, &m->tetrahedra_around_vertex,
                         &m->quads_around_vertex, &m->hexahedra_around_vertex})
      if (!shells->empty() && shells->size() < m->nb_points) shells->resize(m->nb_points);
    mesh_ = std::move(m);
    // The lists now differ from any linked source (a loader's output).
    for (BaseField* f : std::initializer_list<BaseField*>{&edges_f, &triangles_f, &tetrahedra_f, &quads_f, &hexahedra_f})
      if (f->parent()) f->set_parent(nullptr);
  }
  // Written in place; end_edit moves the versions of what changed.
  mesh_->edges = &edges_f.raw();
  mesh_->triangles = &triangles_f.raw();
  mesh_->tetrahedra = &tetrahedra_f.raw();
  mesh_->quads = &quads_f.raw();
  mesh_->hexahedra = &hexahedra_f.raw();
  return *mesh_;
}

void PointSetTopologyContainer::end_edit(bool edges_changed, bool triangles_changed, bool tetrahedra_changed,
                                         bool quads_changed, bool hexahedra_changed) {
  if (!mesh_) return;
  if (edges_changed) edges_f.touch();
  if (triangles_changed) triangles_f.touch();
  if (tetrahedra_changed) tetrahedra_f.touch();
  if (quads_changed) quads_f.touch();
  if (hexahedra_changed) hexahedra_f.touch();
  if (nb_points_f.value() != mesh_->nb_points) nb_points_f.set(mesh_->nb_points);
  mesh_versions_[0] = edges_f.version();
  mesh_versions_[1] = triangles_f.version();
  mesh_versions_[2] = tetrahedra_f.version();
  mesh_versions_[3] = nb_points_f.version();
  mesh_versions_[4] = quads_f.version();
  mesh_versions_[5] = hexahedra_f.version();
}

#define SINEW_LIVE_QUERY(type, name)                                   \
  const type& PointSetTopologyContainer::name() const {                \
    return live() ? mesh_->name : MeshContainer::name();               \
  }
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, edges_around_vertex)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, triangles_around_vertex)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, triangles_around_edge)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, tetrahedra_around_vertex)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, tetrahedra_around_edge)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, tetrahedra_around_triangle)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, quads_around_vertex)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, quads_around_edge)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, hexahedra_around_vertex)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, hexahedra_around_edge)
SINEW_LIVE_QUERY(std::vector<MeshTopologyBase::IndexList>, hexahedra_around_quad)
using EdgesInTriangle = std::vector<std::array<unsigned, 3>>;
using EdgesInTetrahedron = std::vector<std::array<unsigned, 6>>;
using TrianglesInTetrahedron = std::vector<std::array<unsigned, 4>>;
SINEW_LIVE_QUERY(EdgesInTriangle, edges_in_triangle)
SINEW_LIVE_QUERY(EdgesInTetrahedron, edges_in_tetrahedron)
SINEW_LIVE_QUERY(TrianglesInTetrahedron, triangles_in_tetrahedron)
using EdgesInQuad = std::vector<std::array<unsigned, 4>>;
using EdgesInHexahedron = std::vector<std::array<unsigned, 12>>;
using QuadsInHexahedron = std::vector<std::array<unsigned, 6>>;
SINEW_LIVE_QUERY(EdgesInQuad, edges_in_quad)
SINEW_LIVE_QUERY(EdgesInHexahedron, edges_in_hexahedron)
SINEW_LIVE_QUERY(QuadsInHexahedron, quads_in_hexahedron)
#undef SINEW_LIVE_QUERY

unsigned PointSetTopologyContainer::triangle_index(unsigned a, unsigned b, unsigned c) const {
  if (!live()) return MeshContainer::triangle_index(a, b, c);
  // Live shells are not sorted: scan the first vertex's triangles.
  const auto& tav = mesh_->triangles_around_vertex;
  if (a >= tav.size()) return kInvalidIndex;
  const auto& tris = triangles_f.value();
  for (unsigned t : tav[a]) {
    const Triangle& tr = tris[t];
    const bool hb = tr[0] == b || tr[1] == b || tr[2] == b;
    const bool hc = tr[0] == c || tr[1] == c || tr[2] == c;
    if (hb && hc) return t;
  }
  return kInvalidIndex;
}

unsigned PointSetTopologyContainer::quad_index(unsigned a, unsigned b, unsigned c, unsigned d) const {
  if (!live()) return MeshContainer::quad_index(a, b, c, d);
  return topo::find_quad(*mesh_, a, b, c, d);
}

void register_point_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "PointSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for points";
  info.create = creator<PointSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
