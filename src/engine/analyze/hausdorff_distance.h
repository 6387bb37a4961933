// HausdorffDistance: distances between two point clouds (SOFA's
// Engine/Analyze): d12 = max over points1 of the distance to the nearest of
// points2, d21 the reverse, max = the larger. Computed at init and, with
// `update`, at every AnimateBeginEvent (listening is on by default, as SOFA).
// SOFA declares no engine inputs for it: reading the outputs never
// recomputes them. Vec1d, Vec2d, Vec3d.
#pragma once

#include "core/component.h"
#include "core/roles.h"

namespace sinew {

class HausdorffDistance final : public Component {
 public:
  explicit HausdorffDistance(int width);

  Field<FlatVec> points1;
  Field<FlatVec> points2;
  Field<double> d12{this, "d12", 0.0, "distance from cloud 1 to cloud 2", "Output", "length"};
  Field<double> d21{this, "d21", 0.0, "distance from cloud 2 to cloud 1", "Output", "length"};
  Field<double> max{this, "max", 0.0, "symmetric Hausdorff distance", "Output", "length"};
  Field<bool> update{this, "update", false, "recompute at every time step", "Input"};

  void init() override { compute(); }
  void handle_event(Event& e) override;

  void compute();
};

}  // namespace sinew
