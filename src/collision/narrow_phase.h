// BVHNarrowPhase (spec/interaction.md §1.6): for each model pair of the broad
// phase, walks both bounding trees together (a FIFO of cells seeded by the
// roots' children, a LIFO of the cells each one opens) and runs the element
// test on every pair of leaf cubes that overlap within the alarm distance.
// Outputs are kept per pair of models, in SOFA's map order (models by first
// appearance), and keep their capacity from step to step.
#pragma once

#include <vector>

#include "collision/detection.h"
#include "collision/intersection.h"

namespace sinew {

class BVHNarrowPhase final : public Component {
 public:
  void begin();
  void add_pair(const ModelPair& pair, const Intersection& method);
  // Pairs in map order; a pair without outputs this step is left out by users.
  const std::vector<PairOutputs>& outputs() const { return outputs_; }
  std::vector<PairOutputs>& outputs() { return outputs_; }

 private:
  // A range of elements of one level of a model's hierarchy.
  struct Range {
    CollisionModelBase* model = nullptr;
    int level = 0;  // >= 0: coarse cube level; kLeaves: leaf cubes; kElements: the model's elements
    unsigned begin = 0, end = 0;
    bool empty() const { return begin == end; }
  };
  static constexpr int kLeaves = -1, kElements = -2;
  struct Cell {
    Range r1, r2;
  };

  std::vector<DetectionOutput>& outputs_for(CollisionModelBase* m1, CollisionModelBase* m2);
  static Range internal_children(const Range& r, unsigned k);
  static Range external_children(const Range& r, unsigned k);
  static const Aabb& box(const Range& r, unsigned k);
  void visit(const Cell& cell, std::vector<DetectionOutput>& out);
  void final_pairs(const Range& r1, const Range& r2, std::vector<DetectionOutput>& out);

  std::vector<PairOutputs> outputs_;
  FirstSeenIds ids_;
  // Per pair being traversed.
  const Intersection* method_ = nullptr;
  ElementTest test_ = nullptr;
  bool self_ = false;
  double margin_ = 0;
  std::vector<Cell> fifo_, lifo_;
};

}  // namespace sinew
