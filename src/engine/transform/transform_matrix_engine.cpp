#include "engine/transform/transform_matrix_engine.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/registry.h"
#include "io/sofa_quat.h"

namespace sinew {

namespace {
VecN<16> identity4() {
  VecN<16> m = VecN<16>::Zero();
  for (int i = 0; i < 4; ++i) m[i * 5] = 1.0;
  return m;
}
}  // namespace

VecN<16> mat4_product(const VecN<16>& a, const VecN<16>& b) {
  VecN<16> r = VecN<16>::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = a[i * 4] * b[j];
      for (int k = 1; k < 4; ++k) s += a[i * 4 + k] * b[k * 4 + j];
      r[i * 4 + j] = s;
    }
  return r;
}

TransformMatrixEngine::TransformMatrixEngine()
    : in_t(this, "inT", identity4(), "input transformation (4×4, row by row)", "Inputs"),
      out_t(this, "outT", VecN<16>::Zero(), "output transformation (4×4, row by row)", "Outputs") {
  add_input(&in_t);
  add_output(&out_t);
}

TranslateTransformMatrixEngine::TranslateTransformMatrixEngine() { add_input(&translation); }

void TranslateTransformMatrixEngine::do_update() {
  VecN<16> t = identity4();
  const Vec3 v = translation.get();
  for (int i = 0; i < 3; ++i) t[i * 4 + 3] = v[i];
  out_t.set(mat4_product(in_t.get(), t));
}

RotateTransformMatrixEngine::RotateTransformMatrixEngine() { add_input(&rotation); }

void RotateTransformMatrixEngine::do_update() {
  VecN<16> t = identity4();
  const std::array<double, 9> R = io::SQuat::from_euler(rotation.get() * std::numbers::pi / 180.0).matrix();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i * 4 + j] = R[i * 3 + j];
  out_t.set(mat4_product(in_t.get(), t));
}

ScaleTransformMatrixEngine::ScaleTransformMatrixEngine() { add_input(&scale); }

void ScaleTransformMatrixEngine::do_update() {
  VecN<16> t = identity4();
  const Vec3 s = scale.get();
  for (int i = 0; i < 3; ++i) t[i * 5] = s[i];
  out_t.set(mat4_product(in_t.get(), t));
}

void InvertTransformMatrixEngine::do_update() {
  const VecN<16>& m = in_t.get();
  auto f = [&](int i, int j) { return m[i * 4 + j]; };
  // SOFA's 3×3 determinant and adjugate formulas.
  const double det = f(0, 0) * f(1, 1) * f(2, 2) + f(1, 0) * f(2, 1) * f(0, 2) + f(2, 0) * f(0, 1) * f(1, 2) -
                     f(0, 0) * f(2, 1) * f(1, 2) - f(1, 0) * f(0, 1) * f(2, 2) - f(2, 0) * f(1, 1) * f(0, 2);
  double ri[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  if (std::fabs(det) < std::numeric_limits<double>::epsilon()) {
    msg_warning("cannot invert the matrix (singular rotation/scale part): its inverse is taken as zero");
  } else {
    ri[0][0] = (f(1, 1) * f(2, 2) - f(2, 1) * f(1, 2)) / det;
    ri[1][0] = (f(1, 2) * f(2, 0) - f(2, 2) * f(1, 0)) / det;
    ri[2][0] = (f(1, 0) * f(2, 1) - f(2, 0) * f(1, 1)) / det;
    ri[0][1] = (f(2, 1) * f(0, 2) - f(0, 1) * f(2, 2)) / det;
    ri[1][1] = (f(2, 2) * f(0, 0) - f(0, 2) * f(2, 0)) / det;
    ri[2][1] = (f(2, 0) * f(0, 1) - f(0, 0) * f(2, 1)) / det;
    ri[0][2] = (f(0, 1) * f(1, 2) - f(1, 1) * f(0, 2)) / det;
    ri[1][2] = (f(0, 2) * f(1, 0) - f(1, 2) * f(0, 0)) / det;
    ri[2][2] = (f(0, 0) * f(1, 1) - f(1, 0) * f(0, 1)) / det;
  }
  VecN<16> out = out_t.value();  // SOFA writes into the previous value: row 3 set, the rest overwritten
  for (int i = 0; i < 3; ++i) {
    double t = 0;
    for (int k = 0; k < 3; ++k) t += -1. * ri[i][k] * f(k, 3);
    for (int j = 0; j < 3; ++j) out[i * 4 + j] = ri[i][j];
    out[i * 4 + 3] = t;
  }
  for (int j = 0; j < 3; ++j) out[12 + j] = 0.0;
  out[15] = 1.0;
  out_t.set(out);
}

void register_transform_matrix_engines(Registry& r) {
  auto add = [&](const char* name, const char* what, auto make) {
    ComponentInfo info;
    info.name = name;
    info.category = "Engine/Transform";
    info.description = what;
    info.create = make;
    r.add(std::move(info));
  };
  add("TranslateTransformMatrixEngine", "composes the input 4×4 transform with a translation",
      [](const std::string&) -> std::unique_ptr<Component> {
        return std::make_unique<TranslateTransformMatrixEngine>();
      });
  add("RotateTransformMatrixEngine", "composes the input 4×4 transform with a rotation (Euler angles)",
      [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<RotateTransformMatrixEngine>(); });
  add("ScaleTransformMatrixEngine", "composes the input 4×4 transform with a scale",
      [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<ScaleTransformMatrixEngine>(); });
  add("InvertTransformMatrixEngine", "inverts the input 4×4 affine transform",
      [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<InvertTransformMatrixEngine>(); });
}

}  // namespace sinew
