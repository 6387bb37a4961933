// Drawing of collision models (display flag showCollisionModels) and of their bounding
// trees (showBoundingCollisionModels), as SOFA's collision models draw themselves:
// triangles lit in the model's colour (wireframe with showWireframe), lines, points (3 px),
// spheres, tetrahedra by their edges; the bounding tree as the edges of its cubes.
//
// Internal to src/render: draw_list.cpp calls it per node; next_batch and grow_bounds are
// draw_list.cpp's.
#pragma once

#include "render/draw_list.h"

namespace sinew {
class Node;
struct DisplayFlags;
}  // namespace sinew

namespace sinew::render {

Batch& next_batch(DrawList& list, const Component* source, Batch::Kind kind);
void grow_bounds(DrawList& list, const std::vector<float>& x);
// Positions of a state as floats (the first three coordinates of each DoF); false when it has none.
bool state_positions(const MechanicalState& s, std::vector<float>& out);

// A batch rebuilt from nothing this frame (its arrays emptied, their storage kept), and its
// end: dropped when it drew nothing, else counted in the list's bounds.
inline Batch& fresh_batch(DrawList& list, const Component* source, Batch::Kind kind) {
  Batch& b = next_batch(list, source, kind);
  b.positions.clear(), b.normals.clear(), b.colors.clear(), b.indices.clear();
  return b;
}
// Appends point p to the batch's positions.
inline void push_point(Batch& b, const Vec3& p) {
  for (int k = 0; k < 3; ++k) b.positions.push_back(static_cast<float>(p[k]));
}
inline void close_batch(DrawList& list, const Batch& b) {
  if (b.positions.empty()) --list.used;
  else grow_bounds(list, b.positions);
}

// Springs (SpringForceField and the force fields built on it) of `node`: draw_springs.cpp.
void add_springs(DrawList& list, Node& node, const DisplayFlags& flags);

// The region-of-interest engines of `node` (under showBehaviorModels, and PairBoxROI with a
// drawSize also without; `wireframe`: showWireframe's polygon mode): draw_roi.cpp.
void add_rois(DrawList& list, Node& node, bool behavior_models, bool wireframe);

// The projective constraints of `node` that SOFA draws with showBehaviorModels:
// draw_constraints.cpp.
void add_constraints(DrawList& list, Node& node, const DisplayFlags& flags);

// The mappings of `node` that SOFA draws with showMappings: draw_mappings.cpp.
void add_mappings(DrawList& list, Node& node);

// Every collision model of `node`, as `flags` ask.
void add_collision_models(DrawList& list, Node& node, const DisplayFlags& flags);

// SOFA's CollisionModel::getColor4f: the `color` field when the scene sets it, else a colour
// telling simulated / moving / active apart.
std::array<float, 4> collision_color(bool color_set, const std::array<float, 4>& color, bool simulated, bool moving,
                                     bool active);

}  // namespace sinew::render
