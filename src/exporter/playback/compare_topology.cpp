#include "exporter/playback/compare_topology.h"

#include "core/node.h"
#include "core/registry.h"
#include "exporter/playback/topology_view.h"
#include "regression/topology_compare.h"

namespace sinew {

void CompareTopology::init() {
  if (!topology.get() && node()) topology.set(node()->mesh_topology);
  if (!topology.get()) msg_error("topology: no mesh topology in this node, and no 'topology' link: nothing compared");
  errors_ = {};
  compared_ = 0;
  ReadTopology::reset();
}

void CompareTopology::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  const regression::TopologyBlock* b = advance();
  if (!b) return;
  const auto errors = regression::compare_topology_block(*b, topology_view(*topology));
  for (std::size_t type = 0; type < errors.size(); ++type) errors_[type] += errors[type];
  ++compared_;
}

long long CompareTopology::total_error() const {
  long long total = 0;
  for (long long e : errors_) total += e;
  return total;
}

void CompareTopology::cleanup() {
  if (!print_log.get()) return;
  msg_info("compared " + std::to_string(compared_) + " blocks: total error " + std::to_string(total_error()) +
           " (edges " + std::to_string(errors_[0]) + ", triangles " + std::to_string(errors_[1]) + ", quads " +
           std::to_string(errors_[2]) + ", tetrahedra " + std::to_string(errors_[3]) + ", hexahedra " +
           std::to_string(errors_[4]) + ")");
}

void register_compare_topology(Registry& r) {
  ComponentInfo info;
  info.name = "CompareTopology";
  info.category = "Playback";
  info.description = "compares the node's mesh topology with a topology file (WriteTopology's format) at every step";
  info.create = creator<CompareTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
