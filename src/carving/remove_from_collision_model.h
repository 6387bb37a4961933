// Removing the elements a collision model touched (SOFA's TopologicalChangeManager,
// spec/interaction.md §7.5): a carved collision surface is usually the output of a
// topological mapping (Tetra2TriangleTopologicalMapping), so its elements are first
// carried down to the topology that owns them — triangles to the tetrahedra they
// bound, points to the triangles around them — and that topology's modifier removes
// those, the mappings then rebuilding the surface.
//
// Resolving and removing are split so that a caller with several models (the carving
// manager's surface has a triangle and a point model) resolves every request on the
// same, unchanged topology before anything is removed; SOFA removes per model and so
// reads the later models' indices after the first removal renumbered them.
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

// Carries `elements` (indices in `model`) to the elements of the topology that owns
// them. False with `why` when the model's elements cannot be removed (no dynamic
// topology or modifier, a mapping that cannot say where its elements come from).
bool resolve_removal(const CollisionModelBase& model, std::span<const unsigned> elements, RemovalRequest* out,
                     std::string* why);

// Merges `r` into the request for the same topology in `requests`, or appends it.
void merge_request(std::vector<RemovalRequest>& requests, RemovalRequest r);

// Removes the request's elements (warn → propagate → process, then an ending event, as
// SOFA's manager does); returns how many were handed to the modifier.
std::size_t apply_removal(const RemovalRequest& r, std::string* why);

}  // namespace sinew
