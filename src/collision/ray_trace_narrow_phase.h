// RayTraceNarrowPhase (SOFA's RayTraceNarrowPhase; spec/interaction.md §1.6):
// volume contacts between closed surfaces of TriangleOctreeCollisionModels,
// found by casting rays instead of testing element pairs.
//
// For each pair of models (A, B) from the broad phase, A against B then B
// against A: from each vertex of A inside B's box, a ray goes inward (along
// minus the vertex normal). A contact is kept when the ray meets a triangle
// of B facing it before leaving A through a triangle of A facing it (the
// vertex is then inside B): point 1 is the vertex, point 2 the hit on B,
// the normal the vertex normal, the value minus the depth. Each vertex is
// cast once, from the triangle owning it (the P flags). The intersection
// method only serves the broad phase and the response's distances.
#pragma once

#include "collision/narrow_phase.h"

namespace sinew {

class TriangleOctreeCollisionModel;

class RayTraceNarrowPhase final : public NarrowPhase {
 public:
  void detect(const std::vector<ModelPair>& pairs, const Intersection& method) override;

  // Contacts of vertices of `m1` inside `m2`, appended to `out`.
  static void find_pairs_volume(const TriangleOctreeCollisionModel& m1, const TriangleOctreeCollisionModel& m2,
                                std::vector<DetectionOutput>& out);

 private:
  std::vector<std::pair<std::size_t, std::size_t>> jobs_;  // output entries of (A, B) and (B, A)
  std::vector<ModelPair> job_models_;
  bool warned_ = false;
};

}  // namespace sinew
