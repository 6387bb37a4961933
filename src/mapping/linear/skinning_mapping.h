// SkinningMapping (Rigid3d → Vec3d): linear blend skinning. Each output point
// follows up to nbRef frames with weights w_j (summing to 1):
//   out = Σ_j w_j·(c_j + R_j·l_j),  l_j = R0_jᵀ·(p0 − c0_j)
// with p0 the point at init (initPos) and (c0_j, R0_j) the frames' rest
// positions (positions with computeWeightsFromPosition). As SOFA's component:
// - weights not given: the nbRef[0] nearest frames by 1/d² (a coincident frame
//   gets the largest double), kept sorted by decreasing weight, normalised;
//   then normalised again per point over its nbRef entries;
// - nbRef has one value for all points, or one per point (≤ nbRef[0]);
// - a point's frames are used up to the first zero weight;
// - J: v = Σ w_j·v_j + ω_j × r_j, r_j = w_j·R_j·l_j (the weighted lever arm);
//   no geometric stiffness.
// Explicit `weight` and `indices` lists are not supported (refused at init).
#pragma once

#include <vector>

#include "mapping/mapping_base.h"

namespace sinew {

class SkinningMapping final : public MappingBase {
 public:
  SkinningMapping() : MappingBase(StateType::rigid3, StateType::vec3) {}

  Field<std::vector<double>> init_pos{this, "initPos", {}, "output points at init, world frame (default: the output's positions)",
                                      "Mapping", "length"};
  Field<std::vector<unsigned>> nb_ref{this, "nbRef", {4u}, "number of frames influencing each point (one, or one per point)",
                                      "Mapping"};
  Field<std::string> indices{this, "indices", "", "frames of each point (not supported: computed)", "Mapping"};
  Field<std::string> weight{this, "weight", "", "weights of each point's frames (not supported: computed)", "Mapping"};
  Field<bool> compute_from_position{this, "computeWeightsFromPosition", false,
                                    "weights and local points from the frames' positions instead of rest positions",
                                    "Mapping"};
  Field<unsigned> show_from_index{this, "showFromIndex", 0u, "frame whose weights are shown (viewer)", "Visualization"};
  Field<bool> show_weights{this, "showWeights", false, "show the weights (viewer)", "Visualization"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool has_jt_entry() const override { return out_ != nullptr; }
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

  // Per point, its frames and weights (row-major, nbRef[0] slots per point) and the count used.
  const std::vector<unsigned>& frame_index() const { return index_; }
  const std::vector<double>& weights() const { return w_; }
  std::size_t slots() const { return slots_; }
  const std::vector<unsigned>& counts() const { return count_; }

 protected:
  bool init_mapping() override;

 private:
  std::size_t slots_ = 4;           // nbRef[0]: slots per point
  std::vector<unsigned> count_;     // frames read per point (nbRef, cut at the first zero weight)
  std::vector<unsigned> index_;     // slots_ per point
  std::vector<double> w_;           // slots_ per point
  std::vector<double> local_;       // 3 per slot: w·R0ᵀ(p0 − c0)
  std::vector<double> rotated_;     // 3 per slot: R·local at the last apply
};

}  // namespace sinew
