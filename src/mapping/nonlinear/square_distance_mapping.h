// SquareDistanceMapping: one scalar per topology edge, out_e = |x_e1 − x_e0|²
// (spec/mechanics.md §6.7). Input Vec3d (or Rigid3d centres), output Vec1d.
// Jacobian row e: −2u on e0, +2u on e1 (u = x_e1 − x_e0 at the last apply).
// Geometric stiffness: 2λ·I blocks (+ on the diagonal, − off it), for every
// edge if Exact, for edges with λ < 0 if Stabilized (default), none if None.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class SquareDistanceMapping final : public MappingBase {
 public:
  explicit SquareDistanceMapping(StateType in) : MappingBase(in, StateType::vec1) {}

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
  std::vector<double> grad_;  // 2·(x_e1 − x_e0), 3 per edge
  int gs_ = 2;
  int cw_ = 3, dw_ = 3;
};

}  // namespace sinew
