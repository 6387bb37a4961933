// Topological changes (spec/interaction.md §7.2): the events a dynamic
// topology sends while its element lists change, and the handlers through
// which components keeping per-point or per-element data follow them.
//
// Order of a change (warn → propagate → process): the modifier queues the
// events on the container, then propagates them — every handler registered on
// the container sees every queued event (registration order), then a top-down
// visit from the modifier's node updates the topological mappings whose input
// is the container and calls Component::handle_topology_change — and only then
// edits the arrays. Removal events therefore arrive while the removed elements
// can still be read; their indices are sorted in decreasing order, and the
// container applies them as "move the last element into the slot, pop".
#pragma once

#include <cstddef>
#include <vector>

namespace sinew {

class MeshTopologyBase;

enum class TopologyChangeType {
  points_removed,
  edges_removed,
  triangles_removed,
  quads_removed,
  tetrahedra_removed,
  hexahedra_removed,
  // Additions (propagated after the container changed; indices = the new elements, increasing).
  points_added,
  edges_added,
  triangles_added,
  tetrahedra_added,
  quads_added,
  hexahedra_added,
  ending,  // closes each propagated list (SOFA's ENDING_EVENT)
};

struct TopologyChange {
  TopologyChangeType type = TopologyChangeType::ending;
  std::vector<unsigned> indices;  // removals: decreasing order, each < the count before the change
  // Additions that carry them (SOFA's ancestors/coefficients): per new element, the elements it
  // derives from and their weights; empty when none were given.
  std::vector<std::vector<unsigned>> ancestors;
  std::vector<std::vector<double>> coefficients;
};

// A component's per-element data following a container (SOFA's topology-data
// handler). Owned by the component; it detaches itself when destroyed and the
// container detaches every handler when it is destroyed first.
class TopologyHandler {
 public:
  TopologyHandler() = default;
  TopologyHandler(const TopologyHandler&) = delete;
  TopologyHandler& operator=(const TopologyHandler&) = delete;
  virtual ~TopologyHandler();
  // One event of the list being propagated (removals: before the container changes).
  virtual void apply(const MeshTopologyBase& topology, const TopologyChange& change) = 0;
  // Registers on `t` (detaching from a previous topology); nullptr detaches.
  void attach(MeshTopologyBase* t);
  MeshTopologyBase* attached() const { return topology_; }

 private:
  friend class MeshTopologyBase;
  MeshTopologyBase* topology_ = nullptr;
};

// The removal every per-element array applies: for each index (decreasing),
// the last entry moves into the slot, then the array shrinks by one. `stride`
// entries per element (flat arrays). Indices beyond the array are skipped.
template <class T>
void remove_swap_last(std::vector<T>& data, const std::vector<unsigned>& decreasing, std::size_t stride = 1) {
  std::size_t n = data.size() / stride;
  for (unsigned i : decreasing) {
    if (i >= n) continue;
    const std::size_t last = n - 1;
    if (i != last)
      for (std::size_t c = 0; c < stride; ++c) data[i * stride + c] = data[last * stride + c];
    --n;
  }
  data.resize(n * stride);
}

}  // namespace sinew
