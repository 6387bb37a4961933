// DistanceToPlaneMapping: the signed distance of every input point to a plane,
// out_i = x_i·n − p·n with n the unit planeNormal and p = planePoint (SOFA's
// Sofa.Component.Mapping.Linear). Inputs Vec3d, Vec2d, Vec6d (a 6-d "plane"),
// Rigid3d and Rigid2d (their centres); output Vec1d, one value per input point.
// Linear: J row i = n on point i's position derivative.
//
// As SOFA's init applies the mapping before the component is valid, nothing is
// applied during init (not even with applyRestPosition): the output's
// positions and velocities come from the propagation that follows the scene's
// init. A null normal makes the mapping invalid.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class DistanceToPlaneMapping final : public MappingBase {
 public:
  explicit DistanceToPlaneMapping(StateType in) : MappingBase(in, StateType::vec1) {}

  Field<std::vector<double>> plane_normal{this, "planeNormal", {},
                                          "normal of the plane (one value per spatial dimension; normalised at init)",
                                          "Mapping"};
  Field<std::vector<double>> plane_point{this, "planePoint", {}, "a point of the plane", "Mapping", "length"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;
  bool apply_at_init() const override { return false; }

 private:
  std::vector<double> n_;  // unit normal, dim entries
  double offset_ = 0;      // p·n
  int cw_ = 3, dw_ = 3, dim_ = 3;
};

}  // namespace sinew
