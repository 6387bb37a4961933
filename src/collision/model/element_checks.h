// Helpers shared by the collision models: element boxes that are skipped
// (non-finite or degenerate input), neighbourhoods.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <vector>

#include "collision/collision_model.h"
#include "math/sofa_vec.h"  // sofa_normalize

namespace sinew {

inline bool finite_box(const Aabb& b) { return b.min.allFinite() && b.max.allFinite(); }

// An element that must not collide (bad input) gets an inverted box: it never
// overlaps anything and leaves the unions of its ancestors unchanged. The
// first such element of a model is reported once, naming model and element.
Aabb skipped_box(const CollisionModelBase& m, const char* what, unsigned index, const char* why);

// Points joined to point `v` by an edge of the topology (SOFA's getVerticesAroundVertex).
std::vector<unsigned> vertices_around_vertex(const MeshTopologyBase& t, unsigned v);

// The topology a model reads: its `topology` link, else the node's (or an ancestor's).
MeshTopologyBase* model_topology(const CollisionModelBase& m, MeshTopologyBase* linked);

}  // namespace sinew
