// What the phases of a collision pipeline hand each other
// (spec/interaction.md §1.3): model pairs from the broad phase, contact
// candidates per model pair from the narrow phase.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "collision/collision_model.h"
#include "collision/detection_output.h"

namespace sinew {

struct ModelPair {
  CollisionModelBase* first;
  CollisionModelBase* second;
  bool operator==(const ModelPair&) const = default;
};

// Models numbered in the order a map first met them: SOFA's maps keyed by
// model pairs order their keys by such "first seen" ids (§4.1), so their
// iteration order follows the first appearance of each model.
class FirstSeenIds {
 public:
  std::size_t id(const CollisionModelBase* m) {
    auto it = std::find(seen_.begin(), seen_.end(), m);
    if (it != seen_.end()) return static_cast<std::size_t>(it - seen_.begin());
    seen_.push_back(m);
    return seen_.size() - 1;
  }

 private:
  std::vector<const CollisionModelBase*> seen_;
};

// Outputs of the narrow phase for one pair of finest models.
struct PairOutputs {
  ModelPair models;
  std::vector<DetectionOutput> outputs;  // kept from step to step (capacity reused)
  std::pair<std::size_t, std::size_t> key;
};

}  // namespace sinew
