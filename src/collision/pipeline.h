// The collision pipelines (spec/interaction.md §1.1–1.3).
// SubCollisionPipeline runs one detection: bounding trees, broad phase,
// narrow phase, contacts, responses. CollisionPipeline is one such pipeline
// over the components and models found below its node;
// CompositeCollisionPipeline runs several, each over its own models.
#pragma once

#include <vector>

#include "collision/broad_phase.h"
#include "collision/contact_manager.h"
#include "collision/narrow_phase.h"

namespace sinew {

// What one detection works with, and the per-step algorithm over it.
struct CollisionScope {
  std::vector<CollisionModelBase*> models;  // in scene order
  Intersection* intersection = nullptr;
  BruteForceBroadPhase* broad = nullptr;
  NarrowPhase* narrow = nullptr;
  CollisionResponse* manager = nullptr;
  int depth = 6;

  // Empty when complete, else what is missing.
  std::string missing() const;
  // Bounding trees (continuous over dt for CCD methods), broad and narrow
  // phases, contacts (§1.3 steps 1–4).
  void detect(double dt);
  // Attaches each contact's response: obstacle–body contacts in the body's
  // node, body–body contacts in `root` (§1.3 step 5, §4.2).
  void respond(Node& root);

 private:
  std::vector<Node*> touched_;
  std::vector<Component*> wanted_;  // buffers kept from step to step
};

class SubCollisionPipeline final : public Component {
 public:
  Field<int> depth{this, "depth", 6, "number of split levels of the bounding-volume hierarchies", "Collision"};
  MultiLink<CollisionModelBase> collision_models{this, "collisionModels", "collision models of this pipeline"};
  Link<Intersection> intersection_method{this, "intersectionMethod", "intersection method"};
  Link<CollisionResponse> contact_manager{this, "contactManager", "contact manager"};
  Link<BruteForceBroadPhase> broad_phase{this, "broadPhaseDetection", "broad phase"};
  Link<NarrowPhase> narrow_phase{this, "narrowPhaseDetection", "narrow phase"};

  void init() override;
  CollisionScope& scope() { return scope_; }

 private:
  CollisionScope scope_;
};

}  // namespace sinew
