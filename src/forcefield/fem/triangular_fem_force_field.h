// TriangularFEMForceField: plane-stress triangles. Method "large" (default):
// corotational, the strain-displacement matrix J is rebuilt from the current
// local shape every step (spec/mechanics.md §2.7, trap 13); the frame of a
// triangle has x along AB and z along AB×AC. Method "small": J from the
// current x, y coordinates (no rotation), forces in the xy plane (as SOFA).
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew {

class TriangularFEMForceField final : public ForceField {
 public:
  Field<std::string> method{this, "method", "large", "\"large\" (corotational) or \"small\" (linear) displacements",
                            "Material"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.3}, "Poisson's ratio: one value, or one per element", "Material", "dimensionless"};
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {1000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> rotated_initial_elements{this, "rotatedInitialElements", {},
                                                      "rest shape of each element in its frame (unsupported)",
                                                      "Material"};
  Field<std::vector<double>> initial_transformation{this, "initialTransformation", {},
                                                    "rest frame of each element (unsupported)", "Material"};
  Field<double> hosford_exponant{this, "hosfordExponant", 1.0, "exponent of the Hosford yield criterion", "Stress"};
  Field<double> criteria_value{this, "criteriaValue", 1e15,
                               "stress threshold above which triangles are shown as fracturable", "Stress"};
  Field<bool> show_stress_value{this, "showStressValue", true, "render stress values (viewer)", "Visualization"};
  Field<bool> show_stress_vector{this, "showStressVector", false, "render stress directions (viewer)",
                                 "Visualization"};
  Field<bool> show_fracturable_triangles{this, "showFracturableTriangles", false,
                                         "render triangles to fracture (viewer)", "Visualization"};
  Field<bool> compute_principal_stress{this, "computePrincipalStress", false,
                                       "compute the principal stresses of each triangle", "Stress"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  struct Element {
    unsigned a = 0, b = 0, c = 0;
    double rbx = 0, rcx = 0, rcy = 0;  // rest B, C in the rest frame (A at the origin)
    double rby = 0;                    // small: rest B.y (A at the origin, world axes)
    double area = 0;
    std::array<double, 9> D{};         // material matrix × area (row-major 3×3)
    std::array<double, 18> J{};        // strain-displacement (6×3 row-major), from the last add_force
    Mat3 rotation = Mat3::Identity();  // local → world (Rᵀ), from the last add_force
  };

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<Element>& elements() const { return el_; }

 private:
  bool rebuild();
  void add_force_small(const double* x, double* f);
  void add_dforce_small(const double* dx, double* df, double kfactor) const;
  bool small_ = false;
  std::vector<Element> el_;
  std::uint64_t triangles_version_ = 0;  // of the list the elements were built from
};

}  // namespace sinew
