#include "projective/subset_indices.h"

#include <algorithm>

#include "core/roles.h"

namespace sinew {

void follow_point_removal(std::vector<unsigned>& subset, const std::vector<unsigned>& decreasing,
                          std::size_t nb_points) {
  follow_subset_removal(subset, decreasing, nb_points, [](std::size_t) {});
}

void SubsetIndicesFollower::bind(Field<std::vector<unsigned>>* indices, std::vector<std::vector<unsigned>*> extra,
                                 std::function<void()> after) {
  indices_ = indices;
  extra_ = std::move(extra);
  after_ = std::move(after);
}

void SubsetIndicesFollower::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::points_removed || !indices_) return;
  std::vector<unsigned> idx = indices_->get();
  if (indices_->parent()) indices_->set_parent(nullptr);
  follow_point_removal(idx, c.indices, t.nb_points());
  indices_->set(std::move(idx));
  for (std::vector<unsigned>* e : extra_) follow_point_removal(*e, c.indices, t.nb_points());
  if (after_) after_();
}

}  // namespace sinew
