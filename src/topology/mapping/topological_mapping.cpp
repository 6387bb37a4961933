#include "topology/mapping/topological_mapping.h"

#include "topology/dynamic/point_set_topology_container.h"
#include "topology/grid/regular_grid_topology.h"

namespace sinew {

ElementType element_type(const MeshTopologyBase& t) {
  if (auto* c = dynamic_cast<const PointSetTopologyContainer*>(&t)) {
    using L = PointSetTopologyContainer::Level;
    switch (c->level()) {
      case L::point: return ElementType::point;
      case L::edge: return ElementType::edge;
      case L::triangle: return ElementType::triangle;
      case L::quad: return ElementType::quad;
      case L::tetrahedron: return ElementType::tetrahedron;
      case L::hexahedron: return ElementType::hexahedron;
    }
  }
  if (!t.hexahedra().empty()) return ElementType::hexahedron;
  if (!t.tetrahedra().empty()) return ElementType::tetrahedron;
  if (!t.quads().empty()) return ElementType::quad;
  if (!t.triangles().empty()) return ElementType::triangle;
  if (!t.edges().empty()) return ElementType::edge;
  return ElementType::point;
}

const char* element_type_name(ElementType t) {
  switch (t) {
    case ElementType::point: return "Point";
    case ElementType::edge: return "Edge";
    case ElementType::triangle: return "Triangle";
    case ElementType::quad: return "Quad";
    case ElementType::tetrahedron: return "Tetrahedron";
    case ElementType::hexahedron: return "Hexahedron";
  }
  return "?";
}

bool TopologicalMapping::check_links(bool check_types, ElementType in, ElementType out) {
  if (!input) {
    msg_error("no input topology (set input=\"@...\")");
    set_state(ComponentState::invalid);
    return false;
  }
  if (!output) {
    msg_error("No target topology container found.");
    set_state(ComponentState::invalid);
    return false;
  }
  if (check_types) {
    const ElementType ti = element_type(*input);
    if (ti != in) {
      msg_error("The type of the input topology '" + input->describe() + "' (" + element_type_name(ti) +
                ") does not correspond to a valid '" + element_type_name(in) + "' topology.");
      set_state(ComponentState::invalid);
      return false;
    }
    const ElementType to = element_type(*output);
    if (to != out) {
      msg_error("The type of the output topology '" + output->describe() + "' (" + element_type_name(to) +
                ") does not correspond to a valid '" + element_type_name(out) + "' topology.");
      set_state(ComponentState::invalid);
      return false;
    }
  }
  return true;
}

bool TopologicalMapping::input_grid_cells(int& nx, int& ny) const {
  auto* grid = dynamic_cast<RegularGridTopology*>(input.get());
  if (!grid) return false;
  grid->hexahedra();  // make sure the grid is generated
  nx = grid->dims()[0] - 1;
  ny = grid->dims()[1] - 1;
  return true;
}

void TopologicalMapping::update_top_down() {
  if (warned_static_) return;
  warned_static_ = true;
  msg_warning("does not follow topological changes of its input yet: its output keeps its elements");
}

}  // namespace sinew
