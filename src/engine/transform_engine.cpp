#include "engine/transform_engine.h"

#include <cmath>
#include <deque>
#include <functional>

#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"
#include "io/sofa_quat.h"

namespace sinew {

TransformEngine::TransformEngine(StateType type)
    : input_position(this, "input_position", empty_coords(type), "points to transform", "Inputs"),
      output_position(this, "output_position", empty_coords(type), "transformed points", "Outputs"),
      type_(type) {
  for (BaseField* f :
       std::initializer_list<BaseField*>{&input_position, &translation, &rotation, &quaternion, &scale, &inverse})
    add_input(f);
  add_output(&output_position);
}

void TransformEngine::init() { update(); }

void TransformEngine::do_update() {
  using io::SQuat;
  const Vec3 s = scale.get(), r = rotation.get(), t = translation.get();
  SQuat qin;
  for (int i = 0; i < 4; ++i) qin.q[i] = quaternion.get()[i];
  const bool inv = inverse.get();
  const int dim = state_type_info(type_).spatial_dim;
  const bool rigid3 = type_ == StateType::rigid3, rigid2 = type_ == StateType::rigid2;

  // Each operation acts on one coordinate (a pointer to its scalars).
  using Op = std::function<void(double*)>;
  std::deque<Op> ops;
  auto add = [&](Op op) {
    if (inv) ops.push_front(std::move(op));
    else ops.push_back(std::move(op));
  };
  auto get3 = [dim](const double* c) {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < std::min(dim, 3); ++k) p[k] = c[k];
    return p;
  };
  auto set3 = [dim](double* c, const Vec3& p) {
    for (int k = 0; k < std::min(dim, 3); ++k) c[k] = p[k];
  };

  if (!io::sofa_vec_eq(s, Vec3::Ones())) {
    const Vec3 f = inv ? Vec3(1.0 / s[0], 1.0 / s[1], 1.0 / s[2]) : s;
    add([=](double* c) {
      const Vec3 p = get3(c);
      set3(c, Vec3(p[0] * f[0], p[1] * f[1], p[2] * f[2]));
    });
  }
  auto rotation_op = [&](SQuat q, double rot_z) -> Op {
    return [=](double* c) {
      set3(c, q.rotate(get3(c)));
      if (rigid3) {
        SQuat o;
        for (int k = 0; k < 4; ++k) o.q[k] = c[3 + k];
        o = q * o;
        for (int k = 0; k < 4; ++k) c[3 + k] = o.q[k];
      } else if (rigid2) {
        c[2] += rot_z;
      }
    };
  };
  if (!io::sofa_vec_eq(r, Vec3::Zero())) {
    const double k = M_PI / 180.0;
    SQuat q = SQuat::from_euler(Vec3(r[0] * k, r[1] * k, r[2] * k));
    double rot_z = r[2] * (M_PI / 180.0f);
    if (rigid2) {
      if (inv) rot_z = -rot_z;  // the 2-D rigid rotation keeps q un-inverted, as SOFA
    } else if (inv) {
      q = q.inverse();
    }
    add(rotation_op(q, rot_z));
  }
  if (!qin.near(SQuat{})) {
    if (rigid2) {
      msg_error("a quaternion rotation is not available for Rigid2d coordinates");
    } else {
      add(rotation_op(inv ? qin.inverse() : qin, 0.0));
    }
  }
  if (!io::sofa_vec_eq(t, Vec3::Zero())) {
    const Vec3 d = inv ? Vec3(-t[0], -t[1], -t[2]) : t;
    add([=](double* c) {
      const Vec3 p = get3(c);
      set3(c, Vec3(p[0] + d[0], p[1] + d[1], p[2] + d[2]));
    });
  }

  const FlatVec& in = input_position.get();
  FlatVec& out = output_position.edit();
  out.width = in.width;
  out.data = in.data;
  const std::size_t n = out.size();
  for (std::size_t i = 0; i < n; ++i)
    for (const Op& op : ops) op(&out.data[i * out.width]);
}

void register_transform_engine(Registry& r) {
  ComponentInfo info;
  info.name = "TransformEngine";
  info.category = "Engine/Transform";
  info.description = "transforms positions: scale, rotation (Euler or quaternion), translation, or their inverse";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<TransformEngine>();
  r.add(std::move(info));
}

}  // namespace sinew
