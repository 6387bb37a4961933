// RestShapeSpringsForceField: springs pulling points back to their rest
// position (own rest_position, or the positions of `external_rest_shape`):
// f_i −= k_i·(x_i − x0_i) per active direction (spec/mechanics.md §3.7).
// Vec1d/Vec2d/Vec3d states, and Rigid3d: a linear spring on the centre (or on
// a pivot point carried by the frame) and an angular spring on the rotation
// from the rest orientation (axis·angle·angularStiffness).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class RestShapeSpringsForceField final : public ForceField {
 public:
  Field<std::vector<unsigned>> points{this, "points", {}, "indices of the sprung points (default: all)", "Spring"};
  Field<std::vector<double>> stiffness{this, "stiffness", {},
                                       "stiffness per point (or one for all; default 100)", "Spring", "force/length"};
  Field<std::vector<double>> angular_stiffness{this, "angularStiffness", {},
                                               "angular stiffness (rigid states only)", "Spring"};
  Field<std::vector<Vec3>> pivot_points{this, "pivot_points", {}, "global pivot points (rigid states only)",
                                        "Spring"};
  Field<std::vector<unsigned>> external_points{
      this, "external_points", {}, "matching point indices in the external rest-shape state", "Spring"};
  Field<bool> recompute_indices{this, "recompute_indices", true,
                                "recompute the point indices when the state is resized", "Spring"};
  Field<bool> draw_spring{this, "drawSpring", false, "draw the springs (viewer)", "Visualization"};
  Field<std::vector<double>> spring_color{this, "springColor", {0.0, 1.0, 0.0, 1.0}, "spring colour (viewer)",
                                          "Visualization"};
  Field<std::vector<int>> active_directions{
      this, "activeDirections", {1, 1, 1, 1, 1, 1}, "per-component mask: 1 sprung, 0 free", "Spring"};
  Link<MechanicalState> external_rest_shape{this, "external_rest_shape",
                                            "state whose positions define the rest shape"};
  Link<MeshTopologyBase> topology{this, "topology", "topology container (topological changes)"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  // ½·Σ k_i·|x_i − x0_i|² over the active directions (SOFA does not implement it).
  std::optional<double> potential_energy() const override;

 private:
  bool compute_indices();
  const std::vector<double>* rest() const;
  std::vector<unsigned> idx_, ext_idx_;
  void add_force_rigid(const MechParams& p);
  void add_dforce_rigid(const MechParams& p, double kfactor);
  std::vector<double> k_, ka_;
  std::vector<char> active_;
  std::size_t state_size_ = 0;
  int dim_ = 3;  // scalars of a position (Vec) or of a derivative's linear part (rigid: 3)
  bool rigid_ = false;
};

}  // namespace sinew
