// DistanceFromTargetMapping: one scalar per selected input point, its distance
// to a fixed target minus a rest length, out_i = |x[indices[i]] − target_i| − L_i
// (SOFA's Sofa.Component.Mapping.NonLinear). Inputs Vec1d, Vec3d or Rigid3d
// (the centre; orientations are ignored), output Vec1d.
//
// - `indices` shorter than `targetPositions` is completed with i for each
//   further target (SOFA's init); `restLengths` of another size is resized with
//   zeros (the distance itself, not the initial distance: unlike DistanceMapping).
// - J row i: the unit direction u = (x − target)/|x − target| on the point's
//   derivative (u = e_0 below 1e-10, inverse length 0), rebuilt at every apply.
//   For Rigid3d, u has 6 entries whose rotation part is 0.
// - Geometric stiffness, SOFA's: G_i = λ_i/d_i·(I − u uᵀ) with I the identity of the
//   input derivative (for Rigid3d 6×6, so the rotation diagonal gets λ/d although J does
//   not depend on the orientation: SOFA's quirk, kept), for every point with Exact,
//   for points in extension (λ < 0) with Stabilized (the default), none with None.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class DistanceFromTargetMapping final : public MappingBase {
 public:
  explicit DistanceFromTargetMapping(StateType in);

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the input points", "Mapping"};
  Field<FlatVec> target_positions;
  Field<std::vector<double>> rest_lengths{this, "restLengths", {}, "rest distance of each point (default 0)",
                                          "Mapping"};
  Field<std::string> geometric_stiffness{this, "geometricStiffness", "Stabilized",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};
  Field<double> show_object_scale{this, "showObjectScale", 0.0,
                                  "drawing: arrows of this size from the point to its target (0: lines)",
                                  "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {1, 1, 0, 1}, "drawing colour (viewer)",
                                        "Visualization"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool build_geometric_stiffness(MatrixSink& K) override;

  // Last directions (dw per point) and inverse lengths, for tests.
  const std::vector<double>& directions() const { return dir_; }

 protected:
  bool init_mapping() override;

 private:
  // b = (I − u uᵀ)·(λ·inv_length·scale), dw × dw, row-major.
  void gs_block(std::size_t i, double lambda, double scale, double* b) const;

  std::vector<unsigned> idx_;
  std::vector<double> target_;   // cw per point
  std::vector<double> rest_;
  std::vector<double> dir_;      // dw per point
  std::vector<double> invlen_;   // 1 per point
  int gs_ = 2;
  int cw_ = 3, dw_ = 3, dim_ = 3;
};

}  // namespace sinew
