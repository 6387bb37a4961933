// TopologicalMapping: base of the components that build an output topology
// from an input one at init (spec/mechanics.md §5.7): Hexa2Tetra, Tetra2Triangle,
// Hexa2Quad, Quad2Triangle, Triangle2Edge. The output container is cleared,
// receives the input's point count and the mapped elements in SOFA's order,
// then is initialised again (which creates its lower lists).
#pragma once

#include <vector>

#include "topology/mesh_topology.h"

namespace sinew {

// SOFA's ElementType of a topology: a dynamic container's own type, else the
// highest non-empty element list of a static one.
enum class ElementType { point, edge, triangle, quad, tetrahedron, hexahedron };
ElementType element_type(const MeshTopologyBase& t);
const char* element_type_name(ElementType t);

class TopologicalMapping : public Component {
 public:
  Link<MeshTopologyBase> input{this, "input", "source topology"};
  Link<MeshContainer> output{this, "output", "target topology"};

  // The input is changing (spec/interaction.md §7.2: called first in the propagation visit,
  // with input->topology_changes() listing the events). Default: the output does not follow;
  // one warning says so (mappings that follow override this).
  virtual void update_top_down();
  // The output is changing (SOFA's updateTopologicalMappingBottomUp): called on the way back up
  // the propagation visit of the output's modifier, after the subtree of the mapping's node, with
  // output->topology_changes() listing the events. Default: nothing (SOFA's mappings other than
  // SimpleTesselatedTetra do not propagate from output to input).
  virtual void update_bottom_up() {}

  // The input elements output element `out` stands for (SOFA's getGlobIndex then getFromIndex):
  // how a removal asked on the output (a carved collision surface) reaches the input. Appends
  // them to `in`; false when this mapping cannot tell (the default).
  virtual bool input_elements(unsigned /*out*/, std::vector<unsigned>& /*in*/) const { return false; }

 protected:
  bool warned_static_ = false;
  // Common checks: both links resolved; with `check_types`, the input and
  // output types must be `in` and `out` (SOFA's checkTopologyInputTypes).
  bool check_links(bool check_types, ElementType in, ElementType out);
  // First component of type T in the output's node, else its ancestors (SOFA's get<T>()).
  template <class T>
  T* find_from_output() const;
  // Grid dimensions of the input when it is a regular grid (cells along x, y); false otherwise.
  bool input_grid_cells(int& nx, int& ny) const;
};

}  // namespace sinew

#include "core/node.h"

namespace sinew {
template <class T>
T* TopologicalMapping::find_from_output() const {
  Node* n = output ? output->node() : nullptr;
  return n ? n->find_up<T>() : nullptr;
}
}  // namespace sinew
