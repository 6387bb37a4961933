// QuadBendingSprings: SpringForceField with one spring across each pair of
// quads sharing an edge (between the opposite vertices), built at init from
// the topology's quads; stiffness/damping = stiffness[0]/damping[0], rest
// length from the *current* positions (spec/mechanics.md §3.4).
#pragma once

#include "forcefield/spring/spring_force_field.h"

namespace sinew {

class QuadBendingSprings final : public SpringForceField {
 public:
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1),
                              "[first, last] DoF range; springs outside it are ignored (-1: open end)", "Spring"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the quads (default: the node's)"};

  void init() override;
};

}  // namespace sinew
