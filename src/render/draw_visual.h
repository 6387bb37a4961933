// Viewer-side visual components in pictures (shown with showVisualModels):
// VisualBoundingBox as the twelve edges of its box; DataDisplay's mesh coloured through its
// OglColorMap. Called per node by gather().
#pragma once

namespace sinew {
class Node;
}

namespace sinew::render {

struct DrawList;

void add_visual_extras(DrawList& list, Node& node);

}  // namespace sinew::render
