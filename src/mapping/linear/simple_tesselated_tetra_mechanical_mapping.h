// SimpleTesselatedTetraMechanicalMapping: the DoFs of a tetrahedral mesh
// refined by SimpleTesselatedTetraTopologicalMapping (SOFA's
// SimpleTesselatedTetraMechanicalMapping, Vec3d → Vec3d): an output point
// copied from input point i is in[i]; the midpoint of input edge (a, b) is
// (in[a] + in[b]) · 0.5. J is that linear map; Jᵀ adds each output force to
// its point, or half of it to each end of its edge.
//
// The topological mapping is the first one found from this node up; its maps
// (pointMappedFromPoint, pointMappedFromEdge) are read at every use, so they
// follow its topological changes. An output point whose source was removed
// keeps its value (SOFA skips it). Without a topological mapping, SOFA's
// mapping does nothing; Sinew reports it.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class SimpleTesselatedTetraTopologicalMapping;

class SimpleTesselatedTetraMechanicalMapping final : public MappingBase {
 public:
  SimpleTesselatedTetraMechanicalMapping(StateType in, StateType out) : MappingBase(in, out) {}

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;

 private:
  // out = J·in on flat Vec3 arrays; false when there is nothing to map.
  bool map(const std::vector<double>& in, std::vector<double>& out) const;
  SimpleTesselatedTetraTopologicalMapping* topo_map_ = nullptr;
};

}  // namespace sinew
