// TriangleBendingSprings: SpringForceField with one spring between the
// opposite vertices of each pair of triangles sharing an edge, built at init
// from the topology's triangles and its quads (each split into (0,1,2) and
// (0,2,3)), SOFA's TriangleBendingSprings (templates Vec3d, Vec2d).
// Stiffness and damping are stiffness[0] and damping[0] (100 and 5 when
// empty); rest lengths are the current distances. An edge shared by more than
// two triangles links every further triangle to the first one (SOFA's).
#pragma once

#include "forcefield/spring/spring_force_field.h"

namespace sinew {

class TriangleBendingSprings final : public SpringForceField {
 public:
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  void init() override;
};

}  // namespace sinew
