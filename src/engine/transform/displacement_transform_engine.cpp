#include "engine/transform/displacement_transform_engine.h"

#include "core/registry.h"
#include "engine/empty_coords.h"
#include "engine/transform/transform_matrix_engine.h"
#include "io/sofa_quat.h"

namespace sinew {

namespace {
VecN<16> homogeneous(const Vec3& c, const io::SQuat& q) {
  VecN<16> m = VecN<16>::Zero();
  const std::array<double, 9> R = q.matrix();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i * 4 + j] = R[i * 3 + j];
    m[i * 4 + 3] = c[i];
  }
  m[15] = 1.0;
  return m;
}
io::SQuat quat_of(const double* c) {
  io::SQuat q;
  q.q = {c[3], c[4], c[5], c[6]};
  return q;
}
}  // namespace

VecN<16> rigid_homogeneous(const double* c) { return homogeneous(Vec3(c[0], c[1], c[2]), quat_of(c)); }

VecN<16> rigid_inverse_homogeneous(const double* c) {
  const io::SQuat qi = quat_of(c).inverse();
  return homogeneous(-qi.rotate(Vec3(c[0], c[1], c[2])), qi);
}

DisplacementTransformEngine::DisplacementTransformEngine(const char* output_name)
    : x0(this, "x0", empty_coords(StateType::rigid3), "rest frames", "Inputs"),
      x(this, "x", empty_coords(StateType::rigid3), "current frames", "Inputs"),
      displacements(this, output_name, {}, "displacement of each frame from its rest pose (4×4, row by row)",
                    "Outputs") {
  add_input(&x0);
  add_input(&x);
  add_output(&displacements);
}

void DisplacementTransformEngine::init() {
  const FlatVec& r = x0.get();
  inverses_.clear();
  for (std::size_t i = 0; i < r.size(); ++i) inverses_.push_back(rigid_inverse_homogeneous(&r.data[i * 7]));
  set_dirty();
}

void DisplacementTransformEngine::do_update() {
  const FlatVec& c = x.get();
  const std::size_t n = c.size(), n0 = x0.get().size();
  if (n != n0 || n != inverses_.size()) {
    msg_error("x and x0 differ in size (" + std::to_string(n) + " and " + std::to_string(n0) +
              " frames; rest inverses taken at init for " + std::to_string(inverses_.size()) + ")");
    return;
  }
  std::vector<VecN<16>>& d = displacements.edit();
  d.resize(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = mat4_product(rigid_homogeneous(&c.data[i * 7]), inverses_[i]);
}

DisplacementMatrixEngine::DisplacementMatrixEngine() : DisplacementTransformEngine("displaceMats") {
  add_input(&scales);
}

void DisplacementMatrixEngine::init() {
  DisplacementTransformEngine::init();
  rest_inverses_ = inverses_;
  if (scales.get().empty()) scales.set(std::vector<Vec3>(x0.get().size(), Vec3(1, 1, 1)));
  reinit();
}

void DisplacementMatrixEngine::reinit() {
  const std::vector<Vec3>& s = scales.get();
  if (s.size() != rest_inverses_.size()) {
    msg_error("x0 and scales differ in size (" + std::to_string(rest_inverses_.size()) + " and " +
              std::to_string(s.size()) + ")");
    return;
  }
  inverses_.resize(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    VecN<16> S = VecN<16>::Zero();
    for (int k = 0; k < 3; ++k) S[k * 5] = static_cast<double>(static_cast<float>(s[i][k]));
    S[15] = 1.0;
    inverses_[i] = mat4_product(S, rest_inverses_[i]);
  }
  set_dirty();
  update();
}

void DisplacementMatrixEngine::do_update() {
  if (x.get().size() != scales.get().size()) {
    msg_error("x and scales differ in size (" + std::to_string(x.get().size()) + " and " +
              std::to_string(scales.get().size()) + ")");
    return;
  }
  DisplacementTransformEngine::do_update();
}

void register_displacement_transform_engine(Registry& r) {
  ComponentInfo info;
  info.name = "DisplacementTransformEngine";
  info.category = "Engine/Transform";
  info.description = "displacement matrices of rigid frames from their rest poses";
  info.templates = {"Rigid3d,Mat4x4"};
  info.default_template = "Rigid3d,Mat4x4";
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<DisplacementTransformEngine>();
  };
  r.add(std::move(info));
  ComponentInfo m;
  m.name = "DisplacementMatrixEngine";
  m.category = "Engine/Transform";
  m.description = "displacement matrices of rigid frames from their rest poses, with a scale per frame";
  m.templates = {"Rigid3d"};
  m.default_template = "Rigid3d";
  m.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<DisplacementMatrixEngine>();
  };
  r.add(std::move(m));
}

}  // namespace sinew
