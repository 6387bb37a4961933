// BruteForceBroadPhase (spec/interaction.md §1.5): every pair of models whose
// root cubes are within the alarm distance, grouped by the later model.
#pragma once

#include <vector>

#include "collision/detection.h"
#include "collision/intersection.h"

namespace sinew {

class BruteForceBroadPhase final : public Component {
 public:
  Field<std::vector<double>> box{
      this, "box", {}, "if set (min max), only models intersecting this box collide", "Collision", "length"};

  void init() override;
  void begin(const Intersection& method);
  void add_model(CollisionModelBase* m);
  const std::vector<ModelPair>& pairs() const { return pairs_; }

 private:
  const Intersection* method_ = nullptr;
  std::vector<CollisionModelBase*> models_;
  std::vector<ModelPair> pairs_;
  bool use_box_ = false;
  Aabb box_;
};

}  // namespace sinew
