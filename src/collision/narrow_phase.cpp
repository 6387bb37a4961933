#include "collision/narrow_phase.h"

#include "core/registry.h"

namespace sinew {

void BVHNarrowPhase::begin() {
  for (PairOutputs& p : outputs_) p.outputs.clear();
}

std::vector<DetectionOutput>& BVHNarrowPhase::outputs_for(CollisionModelBase* m1, CollisionModelBase* m2) {
  for (PairOutputs& p : outputs_)
    if (p.models.first == m1 && p.models.second == m2) return p.outputs;
  PairOutputs entry;
  entry.models = {m1, m2};
  const std::size_t id1 = ids_.id(m1);
  entry.key = {id1, ids_.id(m2)};
  auto at = std::upper_bound(outputs_.begin(), outputs_.end(), entry.key,
                             [](const auto& key, const PairOutputs& p) { return key < p.key; });
  return outputs_.insert(at, std::move(entry))->outputs;
}

BVHNarrowPhase::Range BVHNarrowPhase::internal_children(const Range& r, unsigned k) {
  if (r.level < 0) return {r.model, kElements, 0, 0};
  const CubeTree::Cube& c = r.model->tree().levels()[r.level][k];
  return {r.model, c.child_level == CubeTree::kLeafLevel ? kLeaves : c.child_level, c.first, c.last};
}

BVHNarrowPhase::Range BVHNarrowPhase::external_children(const Range& r, unsigned k) {
  if (r.level != kLeaves) return {r.model, kElements, 0, 0};
  const unsigned e = r.model->tree().leaves()[k].elem;
  return {r.model, kElements, e, e + 1};
}

const Aabb& BVHNarrowPhase::box(const Range& r, unsigned k) {
  return r.level == kLeaves ? r.model->tree().leaves()[k].box : r.model->tree().levels()[r.level][k].box;
}

void BVHNarrowPhase::final_pairs(const Range& r1, const Range& r2, std::vector<DetectionOutput>& out) {
  for (unsigned i = r1.begin; i < r1.end; ++i)
    for (unsigned j = r2.begin; j < r2.end; ++j)
      if (!self_ || r1.model->element_can_collide(i, *r2.model, j)) test_(*method_, *r1.model, i, *r2.model, j, out);
}

void BVHNarrowPhase::add_pair(const ModelPair& pair, const Intersection& method) {
  CollisionModelBase* m1 = pair.first;
  CollisionModelBase* m2 = pair.second;
  if (!m1->simulated.value() && !m2->simulated.value()) return;
  if (m1->empty() || m2->empty()) return;
  bool swap = false;
  test_ = method.find(m1->kind(), m2->kind(), swap);
  if (!test_) return;
  if (swap) std::swap(m1, m2);
  method_ = &method;
  self_ = m1->node() == m2->node();
  margin_ = method.cube_margin(*m1, *m2);
  std::vector<DetectionOutput>& out = outputs_for(m1, m2);

  // The roots' children seed the FIFO of cells (the roots have no external children).
  fifo_.clear();
  lifo_.clear();
  const Range root1{m1, 0, 0, 1}, root2{m2, 0, 0, 1};
  const Range in1 = internal_children(root1, 0), in2 = internal_children(root2, 0);
  if (!in1.empty() && !in2.empty()) fifo_.push_back({in1, in2});
  for (std::size_t head = 0; head < fifo_.size(); ++head) {
    lifo_.push_back(fifo_[head]);
    while (!lifo_.empty()) {
      const Cell cell = lifo_.back();
      lifo_.pop_back();
      visit(cell, out);
    }
  }
}

// One cell: cube ranges are opened (children pushed on the LIFO, so the last
// pushed is opened first), leaf cube pairs go to the element test.
void BVHNarrowPhase::visit(const Cell& cell, std::vector<DetectionOutput>& out) {
  const Range& r1 = cell.r1;
  const Range& r2 = cell.r2;
  if (r1.level == kElements && r2.level == kElements) {
    final_pairs(r1, r2, out);
    return;
  }
  if (r1.level == kElements || r2.level == kElements) return;  // no element–cube test (SOFA reports it)
  for (unsigned i = r1.begin; i < r1.end; ++i)
    for (unsigned j = r2.begin; j < r2.end; ++j) {
      if (!boxes_overlap(box(r1, i), box(r2, j), margin_)) continue;
      const Range c1 = internal_children(r1, i), c2 = internal_children(r2, j);
      if (!c1.empty()) {
        lifo_.push_back({c1, c2.empty() ? Range{r2.model, r2.level, j, j + 1} : c2});
      } else if (!c2.empty()) {
        lifo_.push_back({Range{r1.model, r1.level, i, i + 1}, c2});
      } else {
        const Range e1 = external_children(r1, i), e2 = external_children(r2, j);
        if (!e1.empty() && !e2.empty())
          final_pairs(e1, e2, out);
        else if (!e1.empty())
          fifo_.push_back({e1, Range{r2.model, r2.level, j, j + 1}});
        else if (!e2.empty())
          fifo_.push_back({Range{r1.model, r1.level, i, i + 1}, e2});
      }
    }
}

void register_bvh_narrow_phase(Registry& r) {
  ComponentInfo info;
  info.name = "BVHNarrowPhase";
  info.category = "Collision/Detection";
  info.description = "narrow phase traversing the bounding-volume hierarchies of each pair of collision models";
  info.aliases = {"ParallelBVHNarrowPhase"};  // same outputs, same order (spec/interaction.md §1.1)
  info.create = creator<BVHNarrowPhase>();
  r.add(std::move(info));
}

}  // namespace sinew
