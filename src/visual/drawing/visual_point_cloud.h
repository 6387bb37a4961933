// VisualPointCloud (SOFA's Sofa.Component.Visual): draws positions as points, spheres or
// (rigid templates) frames. Drawn by src/render (draw_visual.cpp); batch runs only check its
// inputs.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class VisualPointCloud final : public VisualComponent {
 public:
  explicit VisualPointCloud(const std::string& tmpl);

  Field<FlatVec> position;  // coordinates of the template (width 1, 2, 3, 3 for Rigid2d, 7 for Rigid3d)
  Field<std::string> draw_mode{this, "drawMode", "Point", "Point, Sphere, or (rigid templates) Frame",
                               "Visualization"};
  Field<double> point_size{this, "pointSize", 1.0, "size of the points and frames", "Visualization"};
  Field<std::vector<double>> sphere_radius{this, "sphereRadius", {},
                                           "sphere radii (one for all, or one per point)", "Visualization"};
  Field<std::string> color{this, "color", "white", "colour of the points", "Visualization"};
  Field<bool> show_indices{this, "showIndices", false, "draw the index of each point", "Visualization"};
  Field<double> indices_scale{this, "indicesScale", 1.0, "size of the indices", "Visualization"};
  Field<std::string> indices_color{this, "indicesColor", "white", "colour of the indices", "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the points", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  // Rigid3d / Rigid2d template: `position` holds frames (drawMode Frame allowed).
  bool rigid() const { return rigid_; }
  // Where point i is drawn: Vec1 (x, 0, 0); Vec2 and Rigid2 (x, y, θ): (x, y, 0); Vec3 and
  // Rigid3: the first three coordinates.
  Vec3 centre(std::size_t i) const;

 private:
  bool rigid_;
};

}  // namespace sinew
