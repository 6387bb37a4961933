#include "topology/mapping/hexa2_tetra_topological_mapping.h"

#include <utility>

#include "core/registry.h"

namespace sinew {

namespace {
// Vertex pairs along each axis in SOFA's hexahedron numbering.
constexpr unsigned kXEdges[4][2] = {{0, 1}, {4, 5}, {3, 2}, {7, 6}};
constexpr unsigned kYEdges[4][2] = {{4, 7}, {5, 6}, {1, 2}, {0, 3}};
constexpr unsigned kZEdges[4][2] = {{4, 0}, {5, 1}, {6, 2}, {7, 3}};
constexpr unsigned kEvenPattern[6][4] = {{0, 5, 1, 6}, {0, 1, 3, 6}, {1, 3, 6, 2},
                                         {6, 3, 0, 7}, {6, 7, 0, 5}, {7, 5, 4, 0}};
constexpr unsigned kOddPattern[6][4] = {{0, 5, 6, 1}, {0, 1, 6, 3}, {1, 3, 2, 6},
                                        {6, 3, 7, 0}, {6, 7, 5, 0}, {7, 5, 0, 4}};
}  // namespace

void Hexa2TetraTopologicalMapping::split(const Hexa& hexa, unsigned i, int nx, int ny, bool swap,
                                         std::vector<Tetra>& out) {
  Hexa c = hexa;
  bool swapped = false;
  if (swap) {
    const unsigned ux = static_cast<unsigned>(nx), uy = static_cast<unsigned>(ny);
    auto mirror = [&](const unsigned (&pairs)[4][2]) {
      for (const auto& p : pairs) std::swap(c[p[0]], c[p[1]]);
      swapped = !swapped;
    };
    if (!((i % ux) & 1u)) mirror(kXEdges);         // x mirrored on even cells
    if (((i / ux) % uy) & 1u) mirror(kYEdges);     // y on odd rows
    if ((i / (ux * uy)) & 1u) mirror(kZEdges);     // z on odd layers
  }
  const auto& pattern = swapped ? kOddPattern : kEvenPattern;
  for (const auto& t : pattern) out.push_back({c[t[0]], c[t[1]], c[t[2]], c[t[3]]});
}

void Hexa2TetraTopologicalMapping::init() {
  if (!check_links(false, ElementType::hexahedron, ElementType::tetrahedron)) return;
  const std::vector<Hexa> hexas = input->hexahedra();  // copy: the output may alias the input
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);

  int nx = 2, ny = 1;
  input_grid_cells(nx, ny);
  if (nx < 1 || ny < 1) {
    msg_error("the input grid has a single point along x or y: it has no hexahedra to split");
    nx = std::max(nx, 1);
    ny = std::max(ny, 1);
  }
  std::vector<Tetra> tets;
  tets.reserve(hexas.size() * 6);
  for (std::size_t i = 0; i < hexas.size(); ++i)
    split(hexas[i], static_cast<unsigned>(i), nx, ny, swapping.value(), tets);
  output->tetrahedra_f.set(std::move(tets));
  output->init();
}

void register_hexa2_tetra_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Hexa2TetraTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where HexahedronSetTopology is converted to TetrahedronSetTopology";
  info.create = creator<Hexa2TetraTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
