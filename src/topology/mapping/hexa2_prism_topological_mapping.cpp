// Hexa2PrismTopologicalMapping: splits each hexahedron of the input into two
// triangular prisms of the output MeshTopology (SOFA's
// Hexa2PrismTopologicalMapping). With SOFA's hexahedron numbering (0–3 the
// bottom face, 4–7 the top), the split goes through the diagonal plane
// (0, 5, 6, 3): prisms (0, 5, 1 | 3, 6, 2) and (0, 4, 5 | 3, 7, 6), the same
// pattern in every cell so that neighbours share faces. The output keeps the
// input's points. Topological changes of the input are not followed (SOFA's
// mapping does not either: it warns).
#include <string>
#include <vector>

#include "core/registry.h"
#include "topology/mapping/topological_mapping.h"
#include "topology/mesh_topology.h"

namespace sinew {

namespace {

class Hexa2PrismTopologicalMapping final : public TopologicalMapping {
 public:
  void init() override {
    if (!check_links(false, ElementType::hexahedron, ElementType::hexahedron)) return;
    auto* out = dynamic_cast<MeshTopology*>(output.get());
    if (!out) {
      msg_error("the output topology " + output->describe() + " cannot hold prisms: use a MeshTopology");
      set_state(ComponentState::invalid);
      return;
    }
    const std::vector<Hexa> hexas = input->hexahedra();  // copy: the output may alias the input
    const std::size_t np = input->nb_points();
    out->clear_topology();
    out->set_nb_points(np);
    std::vector<Prism> prisms;
    prisms.reserve(hexas.size() * 2);
    for (const Hexa& c : hexas) {
      prisms.push_back({c[0], c[5], c[1], c[3], c[6], c[2]});
      prisms.push_back({c[0], c[4], c[5], c[3], c[7], c[6]});
    }
    out->prisms.set(std::move(prisms));
    out->init();
  }
};

}  // namespace

void register_hexa2_prism_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Hexa2PrismTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where HexahedronSetTopology is converted to PrismSetTopology";
  info.create = creator<Hexa2PrismTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
