// DistanceMapping: one scalar per topology edge, out_e = |x_e1 − x_e0| − L0_e
// (spec/mechanics.md §6.5). Input Vec3d (or the centres of Rigid3d), output Vec1d.
//
// restLengths: if its size differs from the edge count it is resized (new
// entries 0) and, unless computeDistance, filled with the initial lengths.
// Jacobian row e: −n on e0, +n on e1 (n = unit direction at the last apply;
// (1,1,1)/√3 when the edge is degenerate). Geometric stiffness (applyDJT):
// G = λ/d·(I − n nᵀ) with λ the output force, for every edge if Exact, for
// edges in extension (λ < 0) if Stabilized, none if None.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class DistanceMapping final : public MappingBase {
 public:
  explicit DistanceMapping(StateType in) : MappingBase(in, StateType::vec1) {}

  Field<bool> compute_distance{
      this, "computeDistance", false,
      "output the distance itself (rest length 0) instead of the elongation from the initial length", "Mapping"};
  Field<std::vector<double>> rest_lengths{
      this,
      "restLengths",
      {},
      "rest length of each edge (default: initial lengths, or 0 with computeDistance)",
      "Mapping"};
  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};
  Field<double> show_object_scale{this, "showObjectScale", 0.0, "drawing scale (viewer)", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {1, 1, 0, 1}, "drawing colour (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology used by this component (default: the node's)"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

 protected:
  bool init_mapping() override;

 private:
  std::vector<Edge> edges_;
  std::vector<double> rest_;
  std::vector<double> dir_;      // 3 per edge
  std::vector<double> invlen_;   // 1 per edge
  int gs_ = 2;
  int cw_ = 3, dw_ = 3;          // input layout (Rigid3d: 7 / 6, centre first)
};

}  // namespace sinew
