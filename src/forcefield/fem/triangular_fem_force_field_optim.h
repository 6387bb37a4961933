// TriangularFEMForceFieldOptim: corotational plane-stress triangles with the
// rest shape kept in a 2D local frame (A at 0, B on x, C in the xy plane)
// and the frame rebuilt from the current edges each step
// (spec/mechanics.md §2.6; trap 13: μ' = E/(1+ν) = 2G, shear term μ'/2).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class TriangularFEMForceFieldOptim final : public ForceField {
 public:
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {5000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio in [0, 0.5): one value, or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "large", "only \"large\" is implemented (other values: warning)",
                            "Material"};
  Field<double> damping{this, "damping", 0.0, "damping-to-stiffness ratio (unused)", "Material", "force·time/length"};
  Field<double> rest_scale{this, "restScale", 1.0, "rest-shape scale factor (pre-stretch when < 1)", "Material"};
  Field<bool> compute_principal_stress{this, "computePrincipalStress", false,
                                       "compute the principal stresses of each triangle", "Stress"};
  Field<double> stress_max_value{this, "stressMaxValue", 0.0, "largest stress over all triangles (output)", "Stress"};
  Field<bool> show_stress_vector{this, "showStressVector", false, "render stress directions (viewer)",
                                 "Visualization"};
  Field<double> show_stress_threshold{this, "showStressThreshold", 0.0,
                                      "only render stress vectors above this value (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  struct TriangleInfo {
    unsigned a = 0, b = 0, c = 0;
    double bx = 0, cx = 0, cy = 0, ss_factor = 0;  // rest shape in the local frame, 1/(4·area)
    double mu = 0, gamma = 0;                      // E/(1+ν), Eν/(1−ν²)
  };
  struct TriangleState {
    Vec3 e0 = Vec3::UnitX(), e1 = Vec3::UnitY();  // current frame (rows of the 2×3 frame)
    Vec3 stress = Vec3::Zero();
  };

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<TriangleInfo>& triangle_info() const { return info_; }
  const std::vector<TriangleState>& triangle_state() const { return tstate_; }

 private:
  bool rebuild();
  std::vector<TriangleInfo> info_;
  std::vector<TriangleState> tstate_;
  std::uint64_t triangles_version_ = 0;  // of the list the elements were built from
};

}  // namespace sinew
