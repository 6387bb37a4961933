#include "collision/model/element_checks.h"

#include <string>

#include "core/node.h"

namespace sinew {

Aabb skipped_box(const CollisionModelBase& m, const char* what, unsigned index, const char* why) {
  m.warn_once(std::string(what) + " " + std::to_string(index) + " has " + why +
              ": skipped by collision detection (further such elements of this model are skipped silently)");
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {Vec3::Constant(inf), Vec3::Constant(-inf)};
}

std::vector<unsigned> vertices_around_vertex(const MeshTopologyBase& t, unsigned v) {
  std::vector<unsigned> out;
  const auto& around = t.edges_around_vertex();
  if (v >= around.size()) return out;
  const auto& edges = t.edges();
  for (unsigned e : around[v]) out.push_back(edges[e][0] == v ? edges[e][1] : edges[e][0]);
  return out;
}

MeshTopologyBase* model_topology(const CollisionModelBase& m, MeshTopologyBase* linked) {
  return linked ? linked : m.node()->get_mesh_topology_link();
}

}  // namespace sinew
