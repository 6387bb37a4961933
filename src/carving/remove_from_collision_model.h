// Removing the elements a collision model touched (SOFA's TopologicalChangeManager,
// spec/interaction.md §7.5): a carved collision surface is usually the output of a
// topological mapping (Tetra2TriangleTopologicalMapping), so its elements are first
// carried down to the topology that owns them — triangles to the tetrahedra they
// bound, points to the triangles around them — and that topology's modifier removes
// those, the mappings then rebuilding the surface.
//
// Resolving and removing are split so that a caller can keep element indices valid across
// removals (the carving manager's PickedElements) before resolving them.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace sinew {

class CollisionModelBase;
class MeshTopologyBase;
class PointSetTopologyModifier;

// Elements to remove from one topology, and the modifier that removes them.
struct RemovalRequest {
  MeshTopologyBase* topology = nullptr;
  PointSetTopologyModifier* modifier = nullptr;
  std::vector<unsigned> elements;  // of the topology's own kind, distinct, decreasing
};

// The topology a model's elements index: its `topology` link, else its node's (SOFA's
// getCollisionTopology); nullptr when there is none.
MeshTopologyBase* collision_topology(const CollisionModelBase& model);

// Carries `elements` (indices in `model`) to the elements of the topology that owns
// them. False with `why` when the model's elements cannot be removed (no dynamic
// topology or modifier, a mapping that cannot say where its elements come from).
bool resolve_removal(const CollisionModelBase& model, std::span<const unsigned> elements, RemovalRequest* out,
                     std::string* why);

// Removes the request's elements (warn → propagate → process, then an ending event, as
// SOFA's manager does); returns how many were handed to the modifier.
std::size_t apply_removal(const RemovalRequest& r, std::string* why);

}  // namespace sinew
