// CylinderVisualModel (SOFA's Sofa.Component.Visual): a visual state (so a mapping may move its
// points) drawn as one lit cylinder per edge. Drawn by src/render (draw_visual.cpp); batch runs
// keep its positions up to date and check its inputs.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class CylinderVisualModel final : public VisualState {
 public:
  Field<FlatVec> position{this, "position", FlatVec{}, "positions of the cylinder ends", "Vector", "length"};
  Field<FlatVec> rest_position{this, "restPosition", FlatVec{}, "rest positions", "Vector", "length"};
  Field<double> radius{this, "radius", 1.0, "radius of the cylinders", "Visualization", "length"};
  Field<std::string> color{this, "color", "white", "colour of the cylinders", "Visualization"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "one cylinder per edge (two position indices)", "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the cylinders", "Visualization"};

  std::size_t visual_size() const override { return position.value().size(); }
  void visual_resize(std::size_t n) override { position.edit().data.resize(n * 3, 0.0); }
  std::vector<double>* visual_vec(int id) override {
    if (id == kRestPosition) return &rest_position.edit().data;
    if (id == kPosition || id >= kFirstDynamicVec) return &position.edit().data;
    return nullptr;
  }

  void parse(AttributeMap& attrs, Diagnostics& diag) override;

  void init() override;
};

}  // namespace sinew
