#include "topology/mapping/hexa2_quad_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/quad_set_topology_modifier.h"

namespace sinew {

void Hexa2QuadTopologicalMapping::init() {
  if (!check_links(true, ElementType::hexahedron, ElementType::quad)) return;
  if (!find_from_output<QuadSetTopologyModifier>()) {
    msg_error("No QuadSetTopologyModifier found in the output topology node '" + output->node()->name.value() +
              "'.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Quad> quads = input->quads();
  const auto& around = input->hexahedra_around_quad();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  std::vector<Quad> out;
  const bool flip = flip_normals.value();
  for (std::size_t i = 0; i < quads.size(); ++i) {
    if (i >= around.size() || around[i].size() != 1) continue;
    const Quad& q = quads[i];
    out.push_back(flip ? Quad{q[3], q[2], q[1], q[0]} : q);
  }
  output->quads_f.set(std::move(out));
  output->init();
}

void register_hexa2_quad_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Hexa2QuadTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where HexahedronSetTopology is converted to QuadSetTopology";
  info.create = creator<Hexa2QuadTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
