#include "engine/transform/smooth_mesh_engine.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

SmoothMeshEngine::SmoothMeshEngine() {
  add_input(&input_position);
  add_input(&input_indices);
  add_input(&nb_iterations);
  add_output(&output_position);
}

void SmoothMeshEngine::init() {
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology: set 'topology' or put one in the node or above");
    set_state(ComponentState::invalid);
    return;
  }
  set_dirty();
}

void SmoothMeshEngine::do_update() {
  if (!topology || state() == ComponentState::invalid) return;
  const std::vector<Vec3>& in = input_position.get();
  const std::vector<unsigned>& ids = input_indices.get();
  const MeshTopologyBase& topo = *topology;
  const std::vector<MeshTopologyBase::IndexList>& around = topo.edges_around_vertex();
  const std::vector<Edge>& edges = topo.edges();
  std::vector<Vec3> out = in;
  for (const MeshTopologyBase::IndexList& shell : around)
    for (unsigned e : shell)
      if (e >= edges.size() || edges[e][0] >= in.size() || edges[e][1] >= in.size()) {
        msg_error("the topology's edges refer to points beyond the " + std::to_string(in.size()) +
                  " input points: output = input");
        output_position.set(std::move(out));
        return;
      }
  // Mean of the neighbours of vertex i in `x` (SOFA's order), or x[i] without any.
  auto mean = [&](const std::vector<Vec3>& x, unsigned i) -> Vec3 {
    if (i >= around.size() || around[i].empty()) return x[i];
    Vec3 p = Vec3::Zero();
    for (unsigned e : around[i]) p += x[edges[e][0] == i ? edges[e][1] : edges[e][0]];
    return p / static_cast<double>(around[i].size());
  };
  for (unsigned n = 0; n < nb_iterations.get(); ++n) {
    std::vector<Vec3> t = out;
    if (ids.empty()) {
      for (unsigned i = 0; i < out.size(); ++i) t[i] = mean(out, i);
    } else {
      for (unsigned i : ids)
        if (i < out.size()) t[i] = mean(out, i);
    }
    out = std::move(t);
  }
  output_position.set(std::move(out));
}

void register_smooth_mesh_engine(Registry& r) {
  ComponentInfo info;
  info.name = "SmoothMeshEngine";
  info.category = "Engine/Transform";
  info.description = "Laplacian smoothing of a mesh's points over its topology's edges";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<SmoothMeshEngine>(); };
  r.add(std::move(info));
}

}  // namespace sinew
