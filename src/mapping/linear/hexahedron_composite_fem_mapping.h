// HexahedronCompositeFEMMapping: points embedded in a HexahedronCompositeFEMForceFieldAndMass
// move with the fine displacements its homogenization predicts, not with the trilinear
// interpolation of the coarse cell (SOFA's FEM/NonUniform). Vec3d → Vec3d (or a visual model).
//
// At init each output point is located in a hexahedron of the finest level the force field
// used (SOFA's findCube on that virtual level, else findNearestCube: unramified cell indices,
// read as hexahedron indices, as SOFA) with trilinear coordinates. Each fine point takes, for
// every coarse hexahedron whose final weights reach it, W·u of that hexahedron's corner
// displacements in its frame, u = R·x − x₀ (R the force field's element rotation, x₀ the
// initial positions; stored in single precision, as SOFA), brought back by Rᵀ and averaged
// over those hexahedra; the output is the trilinear sum of the fine points. J uses the same
// rotations and weights on velocities; Jᵀ is its adjoint (the single-precision rounding aside).
#pragma once

#include <map>
#include <span>
#include <vector>

#include "forcefield/fem/nonuniform/hexahedron_composite_fem_force_field_and_mass.h"
#include "mapping/mapping_base.h"

namespace sinew {

class SparseGridRamificationTopology;

class HexahedronCompositeFEMMapping final : public MappingBase {
 public:
  HexahedronCompositeFEMMapping() : MappingBase(StateType::vec3, StateType::vec3) {}

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;

  // The fine points as of the last apply (drawn with showMappings), 3 per point.
  const std::vector<Vec3>& fine_points() const { return q_fine_; }

 protected:
  bool init_mapping() override;

 private:
  using Weight3 = Eigen::Matrix<double, 3, 24>;
  // Rotations of the coarse hexahedra and their corners' displacements (single precision, as SOFA).
  // positions: u = R·x − x₀ with the force field's current rotations (kept for J and Jᵀ);
  // else u = R·v with the kept rotations.
  void coarse_displacements(std::span<const Vec3> in, bool positions);

  const HexahedronCompositeFEMForceFieldAndMass* ff_ = nullptr;
  std::vector<Hexa> coarse_hexas_;
  std::vector<Hexa> fine_hexas_;                      // of the finest level used
  std::vector<Vec3> q_coarse0_, q_fine0_, q_fine_;
  std::vector<std::map<unsigned, Weight3>> fine_weights_;  // per fine point: coarse hexahedron → its rows
  std::vector<unsigned> cube_;                        // per output point: fine hexahedron
  std::vector<std::array<double, 8>> bary_;           // per output point: trilinear weights
  std::vector<Eigen::Matrix<double, 24, 1>> u_;       // per coarse hexahedron
  std::vector<Mat3> R_;                               // per coarse hexahedron, at the last apply
  std::vector<Vec3> fine_d_;                          // scratch: fine displacements / forces
};

}  // namespace sinew
