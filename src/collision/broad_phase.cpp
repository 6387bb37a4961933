#include "collision/broad_phase.h"

#include "core/registry.h"

namespace sinew {

void BruteForceBroadPhase::init() {
  const auto& b = box.value();
  use_box_ = false;
  if (b.empty()) return;
  if (b.size() != 6) {
    msg_error("box needs 6 values (min x y z, max x y z); got " + std::to_string(b.size()) + ": ignored");
    return;
  }
  box_.min = Vec3(b[0], b[1], b[2]);
  box_.max = Vec3(b[3], b[4], b[5]);
  use_box_ = box_.min.x() < box_.max.x();
}

void BruteForceBroadPhase::begin(const Intersection& method) {
  method_ = &method;
  models_.clear();
  pairs_.clear();
}

void BruteForceBroadPhase::add_model(CollisionModelBase* m) {
  if (m->empty()) return;
  const Aabb& root = m->tree().root().box;
  if (use_box_ && !boxes_overlap(root, box_, method_->alarm_distance() + m->contact_distance.value())) return;
  // Self pair: a simulated model allowed to collide with itself (the root
  // cubes are tested with the cube–cube test, which every method has).
  if (m->simulated.value() && m->can_collide_with(*m) && boxes_overlap(root, root, method_->cube_margin(*m, *m)))
    pairs_.push_back({m, m});
  for (CollisionModelBase* m2 : models_) {
    if (!m->simulated.value() && !m2->simulated.value()) continue;
    if (!m->can_collide_with(*m2) || !m2->can_collide_with(*m)) continue;
    // The cube–cube test always exists; the element pair is checked by the narrow phase.
    if (boxes_overlap(root, m2->tree().root().box, method_->cube_margin(*m, *m2))) pairs_.push_back({m, m2});
  }
  models_.push_back(m);
}

void register_brute_force_broad_phase(Registry& r) {
  ComponentInfo info;
  info.name = "BruteForceBroadPhase";
  info.category = "Collision/Detection";
  info.description = "broad phase testing the root bounding boxes of every pair of collision models";
  info.aliases = {"ParallelBruteForceBroadPhase"};  // same pairs, same order (spec/interaction.md §1.1)
  info.create = creator<BruteForceBroadPhase>();
  r.add(std::move(info));
}

}  // namespace sinew
