#include "topology/mapping/tetra2_triangle_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

void Tetra2TriangleTopologicalMapping::init() {
  if (!check_links(false, ElementType::tetrahedron, ElementType::triangle)) return;
  if (!modifier) modifier.set(find_from_output<TriangleSetTopologyModifier>());
  if (!modifier)
    msg_warning("No TriangleSetTopologyModifier found in output topology context. Dynamic topological changes "
                "will not be supported.");

  const std::vector<Triangle> tris = input->triangles();
  const auto& around = input->tetrahedra_around_triangle();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  if (no_initial_triangles.value()) return;

  std::vector<Triangle> out;
  const bool flip = flip_normals.value();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    if (i >= around.size() || around[i].size() != 1) continue;
    const Triangle& t = tris[i];
    out.push_back(flip ? Triangle{t[0], t[2], t[1]} : t);
  }
  output->triangles_f.set(std::move(out));
  output->init();
}

void register_tetra2_triangle_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Tetra2TriangleTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where TetrahedronSetTopology is converted to TriangleSetTopology";
  info.create = creator<Tetra2TriangleTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
