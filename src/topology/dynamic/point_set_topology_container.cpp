#include "topology/dynamic/point_set_topology_container.h"

#include "core/registry.h"

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

void register_point_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "PointSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for points";
  info.create = creator<PointSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
