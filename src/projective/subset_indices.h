// Index lists that follow point removals, as SOFA's TopologySubsetIndices
// (`d_indices.createTopologyHandler(topology)` in its projective constraints).
//
// On POINTSREMOVED (indices decreasing, the container not yet changed), for
// each removed point r, with `last` the index the last point has at that
// moment (the count before the change, minus one per point already handled):
//   - every entry equal to r is erased, the order of the others kept;
//   - every entry equal to `last` becomes r (the container moves its last
//     point into the freed slot).
// An empty list stops the walk. Other events leave the list alone.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/field.h"
#include "core/topology_change.h"

namespace sinew {

class Component;

// The list update itself: `decreasing` removed points, `nb_points` before the change.
void follow_point_removal(std::vector<unsigned>& subset, const std::vector<unsigned>& decreasing,
                          std::size_t nb_points);

// The same walk for a subset of any element kind (SOFA's TopologySubsetData::remove) whose
// entries carry data: `erase_at(pos)` is called for each erased entry (positions of one removed
// element in decreasing order) so that parallel arrays drop the same entry.
template <class EraseAt>
void follow_subset_removal(std::vector<unsigned>& subset, const std::vector<unsigned>& decreasing,
                           std::size_t nb_elements, EraseAt&& erase_at) {
  // SOFA reads the last index once before the walk (InvalidID when there are no elements).
  bool have_last = nb_elements > 0;
  unsigned last = have_last ? static_cast<unsigned>(nb_elements - 1) : 0;
  for (unsigned r : decreasing) {
    if (subset.empty()) return;
    for (std::size_t pos = subset.size(); pos-- > 0;)
      if (subset[pos] == r) {
        erase_at(pos);
        subset.erase(subset.begin() + static_cast<std::ptrdiff_t>(pos));
      }
    if (!have_last) continue;
    for (unsigned& v : subset)
      if (v == last) v = r;
    if (last == 0) have_last = false;  // SOFA's index wraps to InvalidID
    else --last;
  }
}

// Keeps a component's index field (and optional lists of the same meaning)
// renumbered. A field fed by a link or an engine is cut from it at the first
// change, since its value no longer matches its source.
class SubsetIndicesFollower final : public TopologyHandler {
 public:
  // `extra`: other lists of point indices the owner keeps (e.g. the in-state subset);
  // `after`: called once the lists changed (caches built from them).
  void bind(Field<std::vector<unsigned>>* indices, std::vector<std::vector<unsigned>*> extra = {},
            std::function<void()> after = {});
  void apply(const MeshTopologyBase& t, const TopologyChange& c) override;

 private:
  Field<std::vector<unsigned>>* indices_ = nullptr;
  std::vector<std::vector<unsigned>*> extra_;
  std::function<void()> after_;
};

}  // namespace sinew
