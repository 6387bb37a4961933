#include "collision/narrow_phase.h"

#include <oneapi/tbb/parallel_for.h>

#include <cstddef>

#include "core/registry.h"

namespace sinew {

std::size_t NarrowPhase::output_index(CollisionModelBase* m1, CollisionModelBase* m2) {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (outputs_[i].models.first == m1 && outputs_[i].models.second == m2) return i;
  PairOutputs entry;
  entry.models = {m1, m2};
  const std::size_t id1 = ids_.id(m1);
  entry.key = {id1, ids_.id(m2)};
  auto at = std::upper_bound(outputs_.begin(), outputs_.end(), entry.key,
                             [](const auto& key, const PairOutputs& p) { return key < p.key; });
  return static_cast<std::size_t>(outputs_.insert(at, std::move(entry)) - outputs_.begin());
}

void BVHNarrowPhase::detect(const std::vector<ModelPair>& pairs, const Intersection& method) {
  for (PairOutputs& p : outputs_) p.outputs.clear();
  // The jobs, in pair order: orientation of each pair (the element test's), its output vector.
  jobs_.clear();
  for (const ModelPair& pair : pairs) {
    CollisionModelBase* m1 = pair.first;
    CollisionModelBase* m2 = pair.second;
    if (!m1->simulated.value() && !m2->simulated.value()) continue;
    if (m1->empty() || m2->empty()) continue;
    bool swap = false;
    const ElementTest test = method.find(m1->kind(), m2->kind(), swap);
    if (!test) continue;
    if (swap) std::swap(m1, m2);
    jobs_.push_back({m1, m2, test, 0});
  }
  // Output entries: created first (an insertion moves the entries after it), then found.
  for (const Job& j : jobs_) output_index(j.m1, j.m2);
  for (Job& j : jobs_) j.output = output_index(j.m1, j.m2);
  if (!parallel_ || jobs_.size() < 2) {
    if (traversals_.empty()) traversals_.resize(1);
    for (const Job& j : jobs_) traversals_[0].run(*j.m1, *j.m2, j.test, method, outputs_[j.output].outputs);
    return;
  }
  // What the tests build lazily (topology neighbourhoods, LocalMinDistance's
  // views) is built here, before the tasks share the models.
  for (const Job& j : jobs_) {
    j.m1->prepare_for_sharing(method.uses_neighbourhoods());
    j.m2->prepare_for_sharing(method.uses_neighbourhoods());
  }
  if (traversals_.size() < jobs_.size()) traversals_.resize(jobs_.size());
  tbb::parallel_for(std::size_t{0}, jobs_.size(), [&](std::size_t k) {
    const Job& j = jobs_[k];
    traversals_[k].run(*j.m1, *j.m2, j.test, method, outputs_[j.output].outputs);
  });
}

BVHNarrowPhase::Traversal::Range BVHNarrowPhase::Traversal::internal_children(const Range& r, unsigned k) {
  if (r.level < 0) return {r.model, kElements, 0, 0};
  const CubeTree::Cube& c = r.model->tree().levels()[r.level][k];
  return {r.model, c.child_level == CubeTree::kLeafLevel ? kLeaves : c.child_level, c.first, c.last};
}

BVHNarrowPhase::Traversal::Range BVHNarrowPhase::Traversal::external_children(const Range& r, unsigned k) {
  if (r.level != kLeaves) return {r.model, kElements, 0, 0};
  const unsigned e = r.model->tree().leaves()[k].elem;
  return {r.model, kElements, e, e + 1};
}

BVHNarrowPhase::Traversal::Boxes BVHNarrowPhase::Traversal::boxes(const Range& r) {
  static_assert(offsetof(CubeTree::Leaf, box) == 0 && offsetof(CubeTree::Cube, box) == 0);
  if (r.level == kLeaves)
    return {reinterpret_cast<const unsigned char*>(r.model->tree().leaves().data()), sizeof(CubeTree::Leaf)};
  return {reinterpret_cast<const unsigned char*>(r.model->tree().levels()[r.level].data()), sizeof(CubeTree::Cube)};
}

void BVHNarrowPhase::Traversal::final_pairs(const Range& r1, const Range& r2, std::vector<DetectionOutput>& out) {
  for (unsigned i = r1.begin; i < r1.end; ++i)
    for (unsigned j = r2.begin; j < r2.end; ++j)
      // SOFA's canCollideWith: within one model, only pairs with i < j, then the model's own rule.
      if (!self_ || ((r1.model != r2.model || i < j) && r1.model->element_can_collide(i, *r2.model, j)))
        test_(*method_, *r1.model, i, *r2.model, j, out);
}

void BVHNarrowPhase::Traversal::run(CollisionModelBase& m1, CollisionModelBase& m2, ElementTest test,
                                    const Intersection& method, std::vector<DetectionOutput>& out) {
  method_ = &method;
  test_ = test;
  self_ = m1.node() == m2.node();
  margin_ = method.cube_margin(m1, m2);
  // The roots' children seed the FIFO of cells (the roots have no external children).
  fifo_.clear();
  lifo_.clear();
  const Range root1{&m1, 0, 0, 1}, root2{&m2, 0, 0, 1};
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
void BVHNarrowPhase::Traversal::visit(const Cell& cell, std::vector<DetectionOutput>& out) {
  const Range& r1 = cell.r1;
  const Range& r2 = cell.r2;
  if (r1.level == kElements && r2.level == kElements) {
    final_pairs(r1, r2, out);
    return;
  }
  if (r1.level == kElements || r2.level == kElements) return;  // no element–cube test (SOFA reports it)
  const Boxes b1 = boxes(r1), b2 = boxes(r2);
  for (unsigned i = r1.begin; i < r1.end; ++i)
    for (unsigned j = r2.begin; j < r2.end; ++j) {
      if (!boxes_overlap(b1[i], b2[j], margin_)) continue;
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
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<BVHNarrowPhase>(); };
  r.add(std::move(info));
  ComponentInfo par;
  par.name = "ParallelBVHNarrowPhase";
  par.category = "Collision/Detection";
  par.description = "BVHNarrowPhase with one task per pair of collision models (same outputs, same order)";
  par.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<BVHNarrowPhase>(true);
  };
  r.add(std::move(par));
}

}  // namespace sinew
