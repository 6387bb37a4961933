// A mesh topology's element lists seen as the flat index arrays of the topology file format
// (regression/topology_file.h), without copying: what WriteTopology writes and what
// CompareTopology and the regression runner compare.
#pragma once

#include "core/roles.h"
#include "regression/topology_file.h"

namespace sinew {

// Edges, triangles, quads, tetrahedra and hexahedra of `t`, in that order. Asking for the
// edges builds them when the container derives them (SOFA's getEdges() does the same). The
// spans are valid until the topology changes.
regression::TopologyView topology_view(const MeshTopologyBase& t);

}  // namespace sinew
