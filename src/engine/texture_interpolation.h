// TextureInterpolation (Vec1d, Vec2d, Vec3d): texture coordinates that show a
// field on a surface (SOFA's Sofa.GL engine of that name). With input_states
// set, u = (s − min)/(max − min) and v = 0 per point, s the first component of
// the state (or the mean of all components with scalarField = 0), min and max
// those of the field or min_value/max_value with manual_scale (an inverted
// range is an error, as SOFA reports it, and gives u = 0/0). Without
// input_states, a planar mapping of input_coordinates on their bounding box:
// the two axes other than the last flat one, each scaled to [0, 1].
// drawPotentiels, showIndicesScale and vertexPloted concern SOFA's GUI
// (value labels, a plot of one vertex's value per step); they are accepted.
#pragma once

#include <vector>

#include "core/engine.h"

namespace sinew {

class TextureInterpolation final : public Engine {
 public:
  explicit TextureInterpolation(int width);

  Field<FlatVec> input_states;
  Field<std::vector<Vec3>> input_coordinates{this, "input_coordinates", {}, "coordinates of the points", "Inputs",
                                             "length"};
  Field<std::vector<Vec2>> output_coordinates{this, "output_coordinates", {}, "texture coordinates", "Outputs"};
  Field<bool> scalar_field{this, "scalarField", true,
                           "use the first component only (else the mean of the components)", "Inputs"};
  Field<double> min_value{this, "min_value", 0.0, "field value at u = 0 (with manual_scale)", "Inputs"};
  Field<double> max_value{this, "max_value", 0.0, "field value at u = 1 (with manual_scale)", "Inputs"};
  Field<bool> manual_scale{this, "manual_scale", false, "use min_value and max_value instead of the field's range",
                           "Inputs"};
  Field<bool> draw_potentiels{this, "drawPotentiels", false, "draw the values (viewer)", "Visualization"};
  Field<double> show_indices_scale{this, "showIndicesScale", static_cast<double>(0.0001f),
                                   "size of the value labels (viewer)", "Visualization"};
  Field<unsigned> vertex_ploted{this, "vertexPloted", 0u, "vertex whose value SOFA's GUI plots per step",
                                "Visualization"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  void planar_mapping();
};

}  // namespace sinew
