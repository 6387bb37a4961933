// BVHNarrowPhase (spec/interaction.md §1.6): for each model pair of the broad
// phase, walks both bounding trees together (a FIFO of cells seeded by the
// roots' children, a LIFO of the cells each one opens) and runs the element
// test on every pair of leaf cubes that overlap within the alarm distance.
// Outputs are kept per pair of models, in SOFA's map order (models by first
// appearance), and keep their capacity from step to step.
//
// ParallelBVHNarrowPhase is the same with one task per model pair (oneTBB):
// each pair writes its own output vector, created beforehand in pair order,
// so the outputs are exactly the sequential ones.
#pragma once

#include <vector>

#include "collision/detection.h"
#include "collision/intersection.h"

namespace sinew {

// What a pipeline asks of a narrow phase: contact candidates per pair of
// models, from the broad phase's model pairs.
class NarrowPhase : public Component {
 public:
  // Detects every pair's contacts (outputs of earlier steps are emptied first).
  virtual void detect(const std::vector<ModelPair>& pairs, const Intersection& method) = 0;
  // Pairs in map order; a pair without outputs this step is left out by users.
  const std::vector<PairOutputs>& outputs() const { return outputs_; }
  std::vector<PairOutputs>& outputs() { return outputs_; }

 protected:
  // The output entry of the ordered pair (m1, m2), created at its place in map order.
  std::size_t output_index(CollisionModelBase* m1, CollisionModelBase* m2);
  std::vector<PairOutputs> outputs_;

 private:
  FirstSeenIds ids_;
};

class BVHNarrowPhase final : public NarrowPhase {
 public:
  explicit BVHNarrowPhase(bool parallel = false) : parallel_(parallel) {}

  void detect(const std::vector<ModelPair>& pairs, const Intersection& method) override;

  // The walk of one pair of trees (its stacks keep their capacity between pairs and steps).
  class Traversal {
   public:
    void run(CollisionModelBase& m1, CollisionModelBase& m2, ElementTest test, const Intersection& method,
             std::vector<DetectionOutput>& out);

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
    static Range internal_children(const Range& r, unsigned k);
    static Range external_children(const Range& r, unsigned k);
    // The boxes of a range's level: leaf cubes and coarse cubes store them at different strides.
    struct Boxes {
      const unsigned char* base;
      std::size_t stride;
      const Aabb& operator[](unsigned k) const { return *reinterpret_cast<const Aabb*>(base + stride * k); }
    };
    static Boxes boxes(const Range& r);
    void visit(const Cell& cell, std::vector<DetectionOutput>& out);
    void final_pairs(const Range& r1, const Range& r2, std::vector<DetectionOutput>& out);

    const Intersection* method_ = nullptr;
    ElementTest test_ = nullptr;
    bool self_ = false;
    double margin_ = 0;
    std::vector<Cell> fifo_, lifo_;
  };

 private:
  struct Job {
    CollisionModelBase* m1;
    CollisionModelBase* m2;
    ElementTest test;
    std::size_t output;  // index in outputs_
  };
  bool parallel_;
  std::vector<Job> jobs_;
  std::vector<Traversal> traversals_;  // one per job in parallel runs, one in sequential runs
};

}  // namespace sinew
