#include "projective/subset_indices.h"

#include <algorithm>

#include "core/roles.h"

namespace sinew {

void follow_point_removal(std::vector<unsigned>& subset, const std::vector<unsigned>& decreasing,
                          std::size_t nb_points) {
  // SOFA reads the last index once before the walk (InvalidID when there are no points).
  bool have_last = nb_points > 0;
  unsigned last = have_last ? static_cast<unsigned>(nb_points - 1) : 0;
  for (unsigned r : decreasing) {
    if (subset.empty()) return;
    subset.erase(std::remove(subset.begin(), subset.end(), r), subset.end());
    if (!have_last) continue;
    std::replace(subset.begin(), subset.end(), last, r);
    if (last == 0) have_last = false;  // SOFA's index wraps to InvalidID
    else --last;
  }
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
