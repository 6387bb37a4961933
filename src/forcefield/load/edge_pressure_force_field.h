// EdgePressureForceField: a load on a subset of a topology's edges, shared
// half and half by each edge's two vertices (SOFA's EdgePressureForceField).
//
// Selection, at init and in SOFA's order (each later one replaces the list):
// the slab dmin < x0·normal < dmax (when dmin != dmax; both vertices inside),
// then `edgeIndices`, then `edges` (vertex pairs looked up as ordered pairs;
// the last match wins, index 0 when absent). The subset then follows the
// topology as SOFA's EdgeSubsetData: a removed edge leaves it (order kept), the
// last edge's index is renamed to the freed slot; added edges never join.
//
// The per-edge force F (each vertex receives F/2), whichever applies first:
//   - pressure != 0: F = pressure · L0, L0 the rest length of the edge;
//   - p_intensity given and binormal set: F = p · n · L, n = normalized
//     (binormal × tangent), the tangent taken on the current positions;
//   - p_intensity given, no binormal: for an edge of the first topology found
//     from the node upwards with exactly one triangle around it,
//     F = p · ((0,0,1) × tangent) · L, oriented towards that triangle's third
//     vertex; other edges keep what the previous update left (0 at first).
// p is p_intensity[i] when the list has more than one value (and an i-th),
// else p_intensity[0]. In both p_intensity modes SOFA takes L as the rest
// length of the i-th edge of the topology, not of the i-th selected edge;
// that is reproduced.
//
// Timing, as SOFA: the forces are computed at init from the positions, and
// add_force applies the stored forces and then computes them again from the
// state's positions, for the next call. No stiffness (SOFA's addDForce adds
// nothing).
#pragma once

#include <vector>

#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

class EdgePressureForceField final : public ForceField {
 public:
  Field<Vec3> pressure{this, "pressure", Vec3::Zero(), "pressure force per unit length", "Load", "force/length"};
  Field<std::vector<unsigned>> edge_indices{this, "edgeIndices", {}, "indices of the loaded edges", "Load"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "loaded edges, as vertex index pairs", "Load"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "normal of the slab selecting the loaded edges", "Load"};
  Field<double> dmin{this, "dmin", 0.0, "lower bound of the selection slab along 'normal'", "Load", "length"};
  Field<double> dmax{this, "dmax", 0.0, "upper bound of the selection slab along 'normal'", "Load", "length"};
  Field<double> arrow_size_coef{this, "arrowSizeCoef", 0.0, "arrow length scale (viewer)", "Visualization"};
  Field<std::vector<double>> p_intensity{this, "p_intensity", {}, "pressure intensity along each edge normal",
                                         "Load"};
  Field<Vec3> binormal{this, "binormal", Vec3::Zero(), "binormal of the 2D plane (edge normals are computed from it)",
                       "Load"};
  Field<bool> show_forces{this, "showForces", false, "draw the pressure forces (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the edges (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }

  // The selected edges (indices in the topology) and their current forces (per edge, before halving).
  const std::vector<unsigned>& selected_edges() const { return map_; }
  const std::vector<Vec3>& edge_forces() const { return force_; }

 private:
  class Follower final : public TopologyHandler {
   public:
    explicit Follower(EdgePressureForceField& ff) : ff_(ff) {}
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;

   private:
    EdgePressureForceField& ff_;
  };

  void select();
  bool check_selection();
  // SOFA's updateEdgeInformation (`with_update`) then initEdgeInformation, from the state's positions.
  void compute_forces(bool with_update);
  void triangle_normal_force(std::size_t i, const std::vector<double>& x, double intensity);

  std::vector<unsigned> map_;  // selected edge indices (SOFA's map2Elements)
  std::vector<double> length_;  // per entry
  std::vector<Vec3> force_;     // per entry, before halving
  MeshTopologyBase* complete_ = nullptr;  // first topology from the node up (the triangle mode)
  Follower follower_{*this};
};

}  // namespace sinew
