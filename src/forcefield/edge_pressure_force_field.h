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
  Field<Vec3> pressure{this, "pressure", Vec3::Zero(), "Pressure force per unit area", "Load"};
  Field<std::vector<unsigned>> edge_indices{this, "edgeIndices", {},
                                            "Indices of edges separated with commas where a pressure is applied",
                                            "Load"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "List of edges where a pressure is applied", "Load"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "Normal direction for the plane selection of edges", "Load"};
  Field<double> dmin{this, "dmin", 0.0, "Minimum distance from the origin along the normal direction", "Load"};
  Field<double> dmax{this, "dmax", 0.0, "Maximum distance from the origin along the normal direction", "Load"};
  Field<double> arrow_size_coef{this, "arrowSizeCoef", 0.0, "Size of the drawn arrows (viewer)", "Visualization"};
  Field<std::vector<double>> p_intensity{this, "p_intensity", {}, "pressure intensity on edge normal", "Load"};
  Field<Vec3> binormal{this, "binormal", Vec3::Zero(), "Binormal of the 2D plane", "Load"};
  Field<bool> show_forces{this, "showForces", false, "draw arrows of edge pressures", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the edges (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

 private:
  bool select();
  std::vector<Edge> selected_;   // vertex pairs of the selected edges
  std::vector<Vec3> force_;      // pressure·L0 per selected edge
  std::size_t n_edges_ = 0;
};

}  // namespace sinew
