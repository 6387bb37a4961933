// The 4×4 affine transform engines of SOFA's Engine/Transform
// (TransformMatrixEngine.h there): each computes outT from inT (default
// identity), matrices row by row (16 values, the form MeshLoader's
// `transformation` takes):
// - TranslateTransformMatrixEngine: outT = inT · T(translation)
// - RotateTransformMatrixEngine:    outT = inT · R(rotation: Euler angles in degrees, SOFA's ZYX quaternion)
// - ScaleTransformMatrixEngine:     outT = inT · diag(scale, 1)
// - InvertTransformMatrixEngine:    outT = [R⁻¹, −R⁻¹·t; 0 0 0 1] (a warning when R is singular)
// Products are summed in SOFA's order.
#pragma once

#include "core/engine.h"

namespace sinew {

class TransformMatrixEngine : public Engine {
 public:
  TransformMatrixEngine();

  Field<VecN<16>> in_t;
  Field<VecN<16>> out_t;

  void init() override { set_dirty(); }
  void reinit() override { update(); }
};

class TranslateTransformMatrixEngine final : public TransformMatrixEngine {
 public:
  TranslateTransformMatrixEngine();
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation", "Inputs", "length"};

 protected:
  void do_update() override;
};

class RotateTransformMatrixEngine final : public TransformMatrixEngine {
 public:
  RotateTransformMatrixEngine();
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "Euler angles (degrees)", "Inputs", "degrees"};

 protected:
  void do_update() override;
};

class ScaleTransformMatrixEngine final : public TransformMatrixEngine {
 public:
  ScaleTransformMatrixEngine();
  Field<Vec3> scale{this, "scale", Vec3::Zero(), "scale along x, y, z", "Inputs"};

 protected:
  void do_update() override;
};

class InvertTransformMatrixEngine final : public TransformMatrixEngine {
 protected:
  void do_update() override;
};

// a · b for row-major 4×4 matrices, summed over k in order (SOFA's Mat product).
VecN<16> mat4_product(const VecN<16>& a, const VecN<16>& b);

}  // namespace sinew
