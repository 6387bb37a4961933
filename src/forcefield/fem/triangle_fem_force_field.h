// TriangleFEMForceField: linear-elastic triangles for a static topology
// (SOFA's TriangleFEMForceField; not TriangularFEMForceField). One Young's
// modulus and Poisson's ratio for all elements, a thickness, plane stress
// (default) or plane strain; elements are the topology's triangles, or its
// quads cut in two (q0 q1 q2, q0 q2 q3) when it has no triangles.
//
// Material per element, V = ½·thickness·|AB × AC| on `initialPoints` (the
// rest positions unless given):
//   plane stress  D = E/(1−ν²)·V·[[1, ν, 0], [ν, 1, 0], [0, 0, (1−ν)/2]]
//   plane strain  D = E/((1+ν)(1−2ν))·V·[[1−ν, ν, 0], [ν, 1−ν, 0], [0, 0, ½−ν]]
// Method "large" (default): corotational. The rest shape is taken in the
// frame R0 of the rest triangle (x along AB, z along AB × AC) as R0·B − R0·A,
// R0·C − R0·A; each add_force rebuilds the frame R and J from the current
// shape, takes Δ = rest − R·(current − A) (B.y left out), f = Rᵀ·J·D·Jᵀ·Δ
// on the sparse pattern of J and D; add_dforce reuses the stored R and J.
// Method "small": world axes, J from the current x, y coordinates of AB and AC
// with the local formula, full products, forces in the xy plane. SOFA's own
// small method reads a rest shape it never computes (it is only filled by the
// large method's init); Sinew takes the rest positions relative to A in world
// axes, which is what the small displacement means.
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew {

class TriangleFEMForceField final : public ForceField {
 public:
  Field<std::vector<Vec3>> initial_points{this, "initialPoints", {},
                                          "rest positions of the elements (default: the state's rest positions)",
                                          "Material", "length"};
  Field<std::string> method{this, "method", "large", "\"large\" (corotational) or \"small\" displacements",
                            "Material"};
  Field<double> poisson_ratio{this, "poissonRatio", 0.3, "Poisson's ratio", "Material", "dimensionless"};
  Field<double> young_modulus{this, "youngModulus", 1000.0, "Young's modulus", "Material",
                              "pressure (force/length²)"};
  Field<double> thickness{this, "thickness", 1.0, "thickness of the elements", "Material", "length"};
  Field<bool> plane_strain{this, "planeStrain", false, "plane strain (else plane stress)", "Material"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  struct Element {
    unsigned a = 0, b = 0, c = 0;
    double rbx = 0, rby = 0, rcx = 0, rcy = 0;  // rest B, C relative to A (large: in the rest frame)
    std::array<double, 9> D{};                  // material matrix × volume (row-major 3×3)
    std::array<double, 18> J{};                 // strain-displacement (6×3 row-major), from the last add_force
    Mat3 rotation = Mat3::Identity();           // local → world, from the last add_force
  };

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<Element>& elements() const { return el_; }

 private:
  bool rebuild();
  bool topology_changed() const;
  void stop(std::size_t element);
  bool small_ = false;
  std::vector<Element> el_;
  std::uint64_t triangles_version_ = 0, quads_version_ = 0;  // of the lists the elements were built from
};

}  // namespace sinew
