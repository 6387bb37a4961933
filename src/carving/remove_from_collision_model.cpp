#include "carving/remove_from_collision_model.h"

#include <algorithm>
#include <set>

#include "collision/collision_model.h"
#include "collision/model/line_collision_model.h"
#include "collision/model/point_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/node.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/point_set_topology_modifier.h"
#include "topology/mapping/topological_mapping.h"

namespace sinew {
namespace {

// The topological mapping of `topo`'s node whose output is `topo` (nullptr: none).
TopologicalMapping* mapping_onto(const MeshTopologyBase& topo) {
  if (!topo.node()) return nullptr;
  for (const auto& o : topo.node()->objects())
    if (auto* m = dynamic_cast<TopologicalMapping*>(o.get()); m && m->output.get() == &topo) return m;
  return nullptr;
}

// Triangles of `topo` (collision-model numbering: its triangles, then two per quad) to the
// elements that own them: the tetrahedron (hexahedron) they bound when `topo` has volumes,
// else themselves (a quad for its two halves).
void surface_owners(const MeshTopologyBase& topo, std::span<const unsigned> tris, std::set<unsigned>& items) {
  if (!topo.tetrahedra().empty()) {
    const auto& shells = topo.tetrahedra_around_triangle();
    for (unsigned t : tris)
      if (t < shells.size() && !shells[t].empty()) items.insert(shells[t][0]);
    return;
  }
  if (!topo.hexahedra().empty()) {
    const auto& shells = topo.hexahedra_around_quad();
    for (unsigned t : tris)
      if (t / 2 < shells.size() && !shells[t / 2].empty()) items.insert(shells[t / 2][0]);
    return;
  }
  const std::size_t nbt = topo.triangles().size();
  for (unsigned t : tris) {
    if (t < nbt) {
      items.insert(t);
    } else if (nbt == 0) {
      items.insert(t / 2);  // quad mesh: halves 2q and 2q + 1 are quad q
    }
    // Halves of the quads of a mixed triangle/quad mesh name no element of one kind: skipped.
  }
}

}  // namespace

MeshTopologyBase* collision_topology(const CollisionModelBase& m) {
  MeshTopologyBase* t = nullptr;
  switch (m.kind()) {
    case CollisionModelBase::Kind::triangle: t = static_cast<const TriangleCollisionModel&>(m).topology.get(); break;
    case CollisionModelBase::Kind::point: t = static_cast<const PointCollisionModel&>(m).topology.get(); break;
    case CollisionModelBase::Kind::line: t = static_cast<const LineCollisionModel&>(m).topology.get(); break;
    default: break;
  }
  if (!t && m.node()) t = m.node()->get_mesh_topology_link();
  return t;
}

bool resolve_removal(const CollisionModelBase& model, std::span<const unsigned> elements, RemovalRequest* out,
                     std::string* why) {
  std::string local;
  if (!why) why = &local;
  MeshTopologyBase* topo = collision_topology(model);
  if (!topo) {
    *why = model.describe() + " has no topology to remove elements from";
    return false;
  }
  std::set<unsigned> items;
  switch (model.kind()) {
    case CollisionModelBase::Kind::triangle:
      surface_owners(*topo, elements, items);
      break;
    case CollisionModelBase::Kind::point: {
      // A point goes with the triangles around it (first-seen order, as SOFA collects them).
      const auto& around = topo->triangles_around_vertex();
      std::vector<unsigned> tris;
      for (unsigned p : elements) {
        if (p >= around.size()) continue;
        for (unsigned t : around[p])
          if (std::find(tris.begin(), tris.end(), t) == tris.end()) tris.push_back(t);
      }
      surface_owners(*topo, tris, items);
      break;
    }
    case CollisionModelBase::Kind::line:
      // Edges are removed from the edge set itself; no mapping is followed (SOFA's manager).
      if (!dynamic_cast<PointSetTopologyContainer*>(topo) || element_type(*topo) != ElementType::edge) {
        *why = "removing lines needs an EdgeSetTopologyContainer";
        return false;
      }
      items.insert(elements.begin(), elements.end());
      break;
    case CollisionModelBase::Kind::sphere:
      // SOFA hands sphere indices to whatever modifier the topology has; only a point set
      // numbers its elements like the spheres.
      if (!dynamic_cast<PointSetTopologyContainer*>(topo) || element_type(*topo) != ElementType::point) {
        *why = "removing spheres needs a PointSetTopologyContainer (its points are the spheres)";
        return false;
      }
      items.insert(elements.begin(), elements.end());
      break;
    default:
      *why = std::string("removing elements of a ") + kind_name(model.kind()) + " collision model is not supported";
      return false;
  }
  // Down the topological mappings to the topology that owns the elements. A mapping that cannot
  // tell where its elements come from (Hexa2Tetra: its input is a grid, built once) ends the
  // walk: its output is a dynamic topology that can lose elements itself. SOFA refuses to carve
  // such a volume; Sinew carves the tetrahedra.
  if (model.kind() != CollisionModelBase::Kind::line) {
    for (int guard = 0; guard < 16; ++guard) {
      TopologicalMapping* m = mapping_onto(*topo);
      if (!m || !m->input.get()) break;
      std::vector<unsigned> from;
      bool known = true;
      for (unsigned e : items) known = known && m->input_elements(e, from);
      if (!known) break;
      items.clear();
      items.insert(from.begin(), from.end());
      topo = m->input.get();
    }
  }
  auto* container = dynamic_cast<PointSetTopologyContainer*>(topo);
  PointSetTopologyModifier* mod = topo->node() ? topo->node()->find_up<PointSetTopologyModifier>() : nullptr;
  if (!container || !mod || mod->container() != topo) {
    *why = topo->describe() + " has no topology modifier in its node (elements can only be removed from a dynamic "
                              "topology: a *SetTopologyContainer with its *SetTopologyModifier)";
    return false;
  }
  out->topology = topo;
  out->modifier = mod;
  out->elements.assign(items.rbegin(), items.rend());
  return true;
}

std::size_t apply_removal(const RemovalRequest& r, std::string* why) {
  if (r.elements.empty() || !r.modifier) return 0;
  if (!r.modifier->remove_items(r.elements, why)) return 0;
  r.modifier->notify_ending_event();
  return r.elements.size();
}

}  // namespace sinew
