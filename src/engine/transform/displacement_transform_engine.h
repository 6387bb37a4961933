// DisplacementTransformEngine (Rigid3d,Mat4x4) and DisplacementMatrixEngine
// (Rigid3d), SOFA's Engine/Transform: the displacement of each frame from its
// rest pose as a 4×4 matrix (row by row): D_i = H(x_i) · H(x0_i)⁻¹, with H the
// homogeneous matrix of a frame and the rest inverses taken once at init, as
// SOFA. DisplacementMatrixEngine inserts a scale: D_i = H(x_i) · S_i · H(x0_i)⁻¹,
// S_i = diag(scales_i as floats, 1) (scales default to 1 1 1 per frame, written
// at init), and names its output displaceMats.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class DisplacementTransformEngine : public Engine {
 public:
  explicit DisplacementTransformEngine(const char* output_name = "displacements");

  Field<FlatVec> x0;
  Field<FlatVec> x;
  Field<std::vector<VecN<16>>> displacements;

  void init() override;

 protected:
  void do_update() override;
  std::vector<VecN<16>> inverses_;  // H(x0_i)⁻¹ (times S_i for the matrix engine)
};

class DisplacementMatrixEngine final : public DisplacementTransformEngine {
 public:
  DisplacementMatrixEngine();

  Field<std::vector<Vec3>> scales{this, "scales", {}, "scale of each frame (default 1 1 1)", "Inputs"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  std::vector<VecN<16>> rest_inverses_;
};

// Homogeneous matrix (row by row) of a Rigid3d coordinate (x y z qx qy qz qw), SOFA's toHomogeneousMatrix.
VecN<16> rigid_homogeneous(const double* c);
// The same for SOFA's Rigid3Types::inverse of the coordinate.
VecN<16> rigid_inverse_homogeneous(const double* c);

}  // namespace sinew
