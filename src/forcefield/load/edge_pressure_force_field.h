// EdgePressureForceField: a pressure (force per unit length, a vector) on a
// set of topology edges — chosen by index, by vertex pairs, or by a slab
// dmin < x·normal < dmax of the rest positions; each vertex of an edge
// receives pressure·L0/2 with L0 the rest length. The intensity-along-the-
// normal mode (p_intensity without pressure) is not supported.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class EdgePressureForceField final : public ForceField {
 public:
  Field<Vec3> pressure{this, "pressure", Vec3::Zero(), "pressure vector (force per unit area)", "Load", "pressure (force/length²)"};
  Field<std::vector<unsigned>> edge_indices{this, "edgeIndices", {}, "indices of the loaded edges", "Load"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "loaded edges, as vertex index pairs", "Load"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "normal of the slab selecting the loaded edges", "Load"};
  Field<double> dmin{this, "dmin", 0.0, "lower bound of the selection slab along 'normal'", "Load", "length"};
  Field<double> dmax{this, "dmax", 0.0, "upper bound of the selection slab along 'normal'", "Load", "length"};
  Field<double> arrow_size_coef{this, "arrowSizeCoef", 0.0, "arrow length scale (viewer)", "Visualization"};
  Field<std::vector<double>> p_intensity{this, "p_intensity", {}, "pressure magnitude along each edge normal", "Load"};
  Field<Vec3> binormal{this, "binormal", Vec3::Zero(), "binormal of the 2D plane (edge normals are computed from it)",
                       "Load"};
  Field<bool> show_forces{this, "showForces", false, "draw the pressure forces (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the edges (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

 private:
  bool select();
  std::vector<Edge> selected_;   // vertex pairs of the selected edges
  std::vector<Vec3> force_;      // pressure·L0 per selected edge
  std::uint64_t edges_version_ = 0;  // of the list the edges were selected from
};

}  // namespace sinew
