#include "topology/mapping/quad2_triangle_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

void Quad2TriangleTopologicalMapping::init() {
  if (!check_links(true, ElementType::quad, ElementType::triangle)) return;
  if (!find_from_output<TriangleSetTopologyModifier>()) {
    msg_error("No TriangleSetTopologyModifier found in the output topology node '" + output->node()->name.value() +
              "'.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Quad> quads = input->quads();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);

  int nx = 2, ny = 1;
  input_grid_cells(nx, ny);
  const int scale = nx == 0 ? ny : nx;
  if (nx == 0 && ny == 0) {
    msg_error("Input topology is only 1D, this topology can't be mapped into a triangulation.");
    set_state(ComponentState::invalid);
    return;
  }
  if (scale <= 0) {
    msg_error("the input grid has no cell along x or y");
    set_state(ComponentState::invalid);
    return;
  }
  const unsigned s = static_cast<unsigned>(scale);
  std::vector<Triangle> out;
  out.reserve(quads.size() * 2);
  for (std::size_t k = 0; k < quads.size(); ++k) {
    const unsigned i = static_cast<unsigned>(k);
    const Quad& q = quads[k];
    if (swapping.value() && (((i % s) ^ (i / s)) & 1u)) {
      out.push_back({q[0], q[1], q[3]});
      out.push_back({q[2], q[3], q[1]});
    } else {
      out.push_back({q[1], q[2], q[0]});
      out.push_back({q[3], q[0], q[2]});
    }
  }
  output->triangles_f.set(std::move(out));
  output->init();
}

void register_quad2_triangle_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Quad2TriangleTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where QuadSetTopology is converted to TriangleSetTopology";
  info.create = creator<Quad2TriangleTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
