// Viewer-side visual components in pictures (shown with showVisualModels):
// VisualBoundingBox as the twelve edges of its box; DataDisplay's mesh coloured through its
// OglColorMap; VisualPointCloud, CylinderVisualModel and VisualMesh as SOFA draws them.
// Called per node by gather().
#pragma once

namespace sinew {
class Node;
class VisualMesh;
}

namespace sinew::render {

struct DrawList;

void add_visual_extras(DrawList& list, Node& node);
// The light sources with drawSource, once the scene's box is known (after the traversal).
void add_light_sources(DrawList& list, Node& root, bool visual_models);
// RecordedCamera's rotation path (drawRotation), whatever the display flags.
void add_camera_paths(DrawList& list, Node& node);

// VisualMesh: draw_visual_mesh.cpp.
void add_visual_mesh(DrawList& list, const VisualMesh& mesh);

}  // namespace sinew::render
