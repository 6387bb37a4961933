#include "mapping/relocation_snapshot.h"

#include "core/node.h"
#include "core/topology_change.h"

namespace sinew {

void RelocationSnapshot::take(const MeshTopologyBase& source, const MechanicalState* in_state,
                              const std::vector<double>& in_now, const MechanicalState* out_state,
                              const std::vector<double>& out_now, std::size_t out_stride) {
  pending = true;
  in = in_now;
  out = out_now;
  auto follows = [&](const MechanicalState* s) {
    return s && s->node() && s->node()->get_mesh_topology_link() == &source;
  };
  const bool in_follows = follows(in_state), out_follows = follows(out_state);
  for (const TopologyChange& c : source.topology_changes())
    if (c.type == TopologyChangeType::points_removed) {
      if (in_follows) remove_swap_last(in, c.indices, 3);
      if (out_follows) remove_swap_last(out, c.indices, out_stride);
    }
}

std::string RelocationSnapshot::select(const std::vector<double>& in_now, const std::vector<double>& out_now,
                                       std::vector<double>& in_pos, std::vector<double>& out_pos,
                                       const std::string& topology, const std::string& doing) {
  const bool fits = pending && in.size() == in_now.size() && out.size() == out_now.size();
  in_pos = fits ? in : in_now;
  out_pos = fits ? out : out_now;
  if (pending || warned_unannounced) return "";
  warned_unannounced = true;
  return "the elements of input topology " + topology +
         " changed without a propagation reaching this mapping (is it outside the modifier's subtree?): " + doing +
         " (SOFA keeps its stale map)";
}

}  // namespace sinew
