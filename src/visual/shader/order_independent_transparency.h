// OrderIndependentTransparencyManager (Sofa.GL.Component.Shader): in the root
// node, the viewer draws the translucent visual models by weighted blended
// order-independent transparency (McGuire & Bavoil 2013) instead of blending
// them in drawing order: each fragment's premultiplied colour is accumulated
// with the weight clamp(0.03 / (1e-5 + (depth·depthScale)⁴), 1e-2, 3e3), the
// product of (1 − alpha) is kept apart, and the sum, normalised, is composed
// over the opaque picture (docs/render.md). SOFA's loop asks only the root
// node's visual managers to draw, so elsewhere the component does nothing.
#pragma once

#include "core/roles.h"

namespace sinew {

class OrderIndependentTransparencyManager final : public VisualComponent {
 public:
  Field<double> depth_scale{this, "depthScale", 0.01, "depth scale of the blending weights (1/length)",
                            "Visualization"};
  void init() override;
};

}  // namespace sinew
