#include "forcefield/spring/joint_spring.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "forcefield/spring/spring_text.h"

namespace sinew::joints {

namespace {

using spring_text::to_double;
using spring_text::to_unsigned;
using spring_text::Tokens;

bool to_flag(std::string_view t, bool& v) {
  unsigned u = 0;
  if (!to_unsigned(t, u) || u > 1) return false;
  v = u == 1;
  return true;
}

std::string fmt(double v) {
  std::ostringstream os;  // std::ostream's default format, as SOFA writes
  os << v;
  return os.str();
}

}  // namespace

std::string parse_joint_springs(std::string_view text, std::vector<JointSpring>& out) {
  out.clear();
  Tokens in{text};
  JointSpring s;  // reused from one spring to the next (carries KS_T, KS_R, KD over)
  std::string_view tok;
  while (in.next(tok)) {
    const std::string where = "spring " + std::to_string(out.size());
    if (tok != "BEGIN_SPRING") return where + ": expected BEGIN_SPRING, found '" + std::string(tok) + "'";
    s.free = {false, false, false, true, true, true};
    s.init_trans = Vec3::Zero();
    s.init_rot = Quat{};
    s.bloc_rot = 0.0;
    s.limits = {-100000., 100000., -100000., 100000., -100000., 100000.};
    bool rest_t = false;
    std::string_view a, b;
    if (!in.next(a) || !in.next(b) || !to_unsigned(a, s.m1) || !to_unsigned(b, s.m2))
      return where + ": BEGIN_SPRING must be followed by two frame indices (non-negative integers)";
    // Reads n numbers after keyword `key` into the given slots.
    auto numbers = [&](std::string_view key, std::initializer_list<double*> slots) {
      return spring_text::read_numbers(in, where, key, slots);
    };
    bool closed = false;
    while (in.next(tok)) {
      std::string err;
      if (tok == "END_SPRING") {
        closed = true;
        break;
      } else if (tok == "FREE_AXIS") {
        for (int i = 0; i < 6 && err.empty(); ++i) {
          std::string_view t;
          if (!in.next(t) || !to_flag(t, s.free[i]))
            err = where + ": FREE_AXIS needs six flags 0 or 1 (tx ty tz rx ry rz)";
        }
      } else if (tok == "KS_T") {
        err = numbers(tok, {&s.soft_trans, &s.hard_trans});
      } else if (tok == "KS_R") {
        err = numbers(tok, {&s.soft_rot, &s.hard_rot});
      } else if (tok == "KS_B") {
        err = numbers(tok, {&s.bloc_rot});
      } else if (tok == "KD") {
        err = numbers(tok, {&s.kd});
      } else if (tok == "R_LIM_X") {
        err = numbers(tok, {&s.limits[0], &s.limits[1]});
      } else if (tok == "R_LIM_Y") {
        err = numbers(tok, {&s.limits[2], &s.limits[3]});
      } else if (tok == "R_LIM_Z") {
        err = numbers(tok, {&s.limits[4], &s.limits[5]});
      } else if (tok == "REST_T") {
        err = numbers(tok, {&s.init_trans[0], &s.init_trans[1], &s.init_trans[2]});
        rest_t = true;
      } else if (tok == "REST_R") {
        err = numbers(tok, {&s.init_rot.x, &s.init_rot.y, &s.init_rot.z, &s.init_rot.w});
      } else {
        err = where + ": unknown keyword '" + std::string(tok) +
              "' (FREE_AXIS, KS_T, KS_R, KS_B, KD, R_LIM_X, R_LIM_Y, R_LIM_Z, REST_T, REST_R, END_SPRING)";
      }
      if (!err.empty()) return err;
    }
    if (!closed) return where + ": missing END_SPRING";
    s.init_from_positions = rest_t;
    if (s.bloc_rot == 0.0) s.bloc_rot = s.hard_rot / 100;
    for (int i = 0; i < 3; ++i)
      if (s.limits[2 * i] == s.limits[2 * i + 1]) s.free[3 + i] = false;
    out.push_back(s);
  }
  return "";
}

std::string format_joint_spring(const JointSpring& s) {
  std::string o = "BEGIN_SPRING  " + std::to_string(s.m1) + " " + std::to_string(s.m2) + "  ";
  const std::array<bool, 6> ball{false, false, false, true, true, true};
  if (s.free != ball) {
    o += "FREE_AXIS";
    for (bool b : s.free) o += b ? " 1" : " 0";
    o += "  ";
  }
  if (s.soft_trans != 0.0 || s.hard_trans != 10000.0) o += "KS_T " + fmt(s.soft_trans) + " " + fmt(s.hard_trans) + "  ";
  if (s.soft_rot != 0.0 || s.hard_rot != 10000.0) o += "KS_R " + fmt(s.soft_rot) + " " + fmt(s.hard_rot) + "  ";
  if (s.bloc_rot != s.hard_rot / 100) o += "KS_B " + fmt(s.bloc_rot) + "  ";
  if (s.kd != 0.0) o += "KD " + fmt(s.kd) + "  ";
  static const char* lim[3] = {"R_LIM_X ", "R_LIM_Y ", "R_LIM_Z "};
  for (int i = 0; i < 3; ++i)
    if (s.limits[2 * i] != -100000 || s.limits[2 * i + 1] != 100000)
      o += lim[i] + fmt(s.limits[2 * i]) + " " + fmt(s.limits[2 * i + 1]) + "  ";
  if (s.init_trans != Vec3::Zero())
    o += "REST_T " + fmt(s.init_trans[0]) + " " + fmt(s.init_trans[1]) + " " + fmt(s.init_trans[2]) + "  ";
  if (s.init_rot.w != 1)
    o += "REST_R " + fmt(s.init_rot.x) + " " + fmt(s.init_rot.y) + " " + fmt(s.init_rot.z) + " " + fmt(s.init_rot.w) +
         "  ";
  o += "END_SPRING\n";
  return o;
}

void quat_to_axis(const Quat& in, Vec3& axis, double& angle) {
  Quat q = in;
  if (q.w < 0) q = {q.x * -1, q.y * -1, q.z * -1, q.w * -1};  // angle in [0, π]
  double sin_half;
  if (q.w > 0.999) {  // below 5°: acos loses accuracy
    sin_half = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    angle = 2.0 * std::asin(sin_half);
  } else {
    const double half = std::acos(q.w);
    sin_half = std::sin(half);
    angle = 2 * half;
  }
  if (sin_half < std::numeric_limits<double>::epsilon()) axis = Vec3(0., 1., 0.);
  else axis = Vec3(q.x / sin_half, q.y / sin_half, q.z / sin_half);
}

namespace {

// Torsion kept inside the limits of the free axes; zero on held axes. Beyond a
// limit, the nearer limit going round the circle (SOFA's projectTorsion).
void project_torsion(const JointSpring& s, JointWork& w) {
  for (int i = 0; i < 3; ++i) {
    const double t = w.torsion[i], lo = s.limits[2 * i], hi = s.limits[2 * i + 1];
    if (!s.free[3 + i]) {
      w.lawful[i] = 0;
    } else if (t > lo && t < hi) {
      w.lawful[i] = t;
    } else {
      double d1, d2;
      if (t > 0) {
        d1 = t - hi;
        d2 = lo + 2 * M_PI - t;
      } else {
        d1 = t - hi + 2 * M_PI;
        d2 = lo - t;
      }
      w.lawful[i] = d1 < d2 ? hi : lo;
    }
  }
}

}  // namespace

void add_joint_spring_force(const JointSpring& s, JointWork& w, const double* x1, const double* v1, double* f1,
                            const double* x2, const double* v2, double* f2, const double* constant) {
  static constexpr double kZero[6] = {};
  if (!constant) constant = kZero;  // still added, as SOFA adds its zero constant force
  const double* p1 = x1 + 7 * s.m1;
  const double* p2 = x2 + 7 * s.m2;
  const Quat q1 = Quat::from(p1 + 3), q2 = Quat::from(p2 + 3);
  w.ref = q1;

  // Second frame relative to the first: centre offset (world frame) and
  // q1⁻¹·q2, then the rest offsets removed.
  Vec3 dp(p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]);
  const double* a1 = v1 + 6 * s.m1;
  const double* a2 = v2 + 6 * s.m2;
  double dv[6];
  for (int i = 0; i < 6; ++i) dv[i] = a2[i] - a1[i];
  dp -= s.init_trans;
  const Quat qrel = quat_normalized(quat_mul(quat_mul(quat_inverse(q1), q2), s.init_rot));

  Vec3 axis;
  double phi;
  quat_to_axis(qrel, axis, phi);
  while (phi < -M_PI) phi += 2 * M_PI;
  while (phi > M_PI) phi -= 2 * M_PI;
  w.torsion = Vec3(axis[0] * phi, axis[1] * phi, axis[2] * phi);

  // Translation: stiffness per local axis of the first frame.
  for (int i = 0; i < 3; ++i) w.kt[i] = !s.free[i] ? s.hard_trans : s.soft_trans;
  w.rel = qrel;
  const Vec3 local = quat_inverse_rotate(w.ref, dp);
  w.local = local;
  const Vec3 lf(constant[0] + w.kt[0] * local[0], constant[1] + w.kt[1] * local[1], constant[2] + w.kt[2] * local[2]);
  const Vec3 rt = quat_rotate(w.ref, lf);
  const Vec3 ft(rt[0] + dv[0] * s.kd, rt[1] + dv[1] * s.kd, rt[2] + dv[2] * s.kd);

  // Rotation.
  for (int i = 0; i < 3; ++i) w.kr[i] = !s.free[3 + i] ? s.hard_rot : s.soft_rot;
  const Vec3& t = w.torsion;
  Vec3 fr0;
  const bool fx = s.free[3], fy = s.free[4], fz = s.free[5];
  if (!fx && !fy && !fz) {  // clamped
    for (int i = 0; i < 3; ++i) fr0[i] = t[i] * w.kr[i];
  } else if (fx && !fy && !fz && t[0] > s.limits[0] && t[0] < s.limits[1]) {
    // Hinge about x inside its limits: the soft twist about x, plus a restoring
    // torque that brings the first frame's x axis image back onto x.
    const Mat3 M = quat_to_matrix(qrel);
    const double cross = std::sqrt(M(1, 0) * M(1, 0) + M(2, 0) * M(2, 0));
    const double th = std::atan2(cross, M(0, 0));
    fr0[0] = t[0] * w.kr[0];
    fr0[1] = -M(2, 0) * th * w.kr[1];
    fr0[2] = M(1, 0) * th * w.kr[2];
  } else if (!fx && fy && !fz && t[1] > s.limits[2] && t[1] < s.limits[3]) {  // hinge about y
    const Mat3 M = quat_to_matrix(qrel);
    const double cross = std::sqrt(M(0, 1) * M(0, 1) + M(2, 1) * M(2, 1));
    const double th = std::atan2(cross, M(1, 1));
    fr0[0] = M(2, 1) * th * w.kr[0];
    fr0[1] = t[1] * w.kr[1];
    fr0[2] = -M(0, 1) * th * w.kr[2];
  } else if (!fx && !fy && fz && t[2] > s.limits[4] && t[2] < s.limits[5]) {  // hinge about z
    const Mat3 M = quat_to_matrix(qrel);
    const double cross = std::sqrt(M(1, 2) * M(1, 2) + M(0, 2) * M(0, 2));
    const double th = std::atan2(cross, M(2, 2));
    fr0[0] = -M(1, 2) * th * w.kr[0];
    fr0[1] = M(0, 2) * th * w.kr[1];
    fr0[2] = t[2] * w.kr[2];
  } else {
    // General case: the part of the torsion beyond the limits (wrapped to
    // (−π, π]) is pulled back with the bloc stiffness on free axes.
    project_torsion(s, w);
    Vec3 extra(t[0] - w.lawful[0], t[1] - w.lawful[1], t[2] - w.lawful[2]);
    double psi = std::sqrt(extra[0] * extra[0] + extra[1] * extra[1] + extra[2] * extra[2]);
    // psi = 0 gives NaN here, as in SOFA; those components are never used then
    // (every axis has torsion == lawful).
    extra = Vec3(extra[0] / psi, extra[1] / psi, extra[2] / psi);
    while (psi < -M_PI) psi += 2 * M_PI;
    while (psi > M_PI) psi -= 2 * M_PI;
    extra = Vec3(extra[0] * psi, extra[1] * psi, extra[2] * psi);
    for (int i = 0; i < 3; ++i)
      if (s.free[3 + i] && t[i] != w.lawful[i]) {  // beyond a limit
        w.kr[i] = s.bloc_rot;
        fr0[i] = extra[i] * w.kr[i];
      } else {
        fr0[i] = t[i] * w.kr[i];
      }
  }
  const Vec3 rr = quat_rotate(w.ref, Vec3(constant[3] + fr0[0], constant[4] + fr0[1], constant[5] + fr0[2]));
  const Vec3 fr(rr[0] + dv[3] * s.kd, rr[1] + dv[4] * s.kd, rr[2] + dv[5] * s.kd);

  w.fr0 = fr0;
  for (int i = 0; i < 3; ++i) w.force[i] = ft[i], w.force[3 + i] = fr[i];
  double* o1 = f1 + 6 * s.m1;
  for (int i = 0; i < 3; ++i) o1[i] += ft[i];
  for (int i = 0; i < 3; ++i) o1[3 + i] += fr[i];
  double* o2 = f2 + 6 * s.m2;
  for (int i = 0; i < 3; ++i) o2[i] -= ft[i];
  for (int i = 0; i < 3; ++i) o2[3 + i] -= fr[i];
}

void add_joint_spring_dforce(const JointSpring& s, const JointWork& w, const double* dx1, double* df1,
                             const double* dx2, double* df2, double k) {
  const double* d1 = dx1 + 6 * s.m1;
  const double* d2 = dx2 + 6 * s.m2;
  const Vec3 dl(d2[0] - d1[0], d2[1] - d1[1], d2[2] - d1[2]);
  const Vec3 da(d2[3] - d1[3], d2[4] - d1[4], d2[5] - d1[5]);
  const Vec3 ll = quat_inverse_rotate(w.ref, dl);
  const Vec3 la = quat_inverse_rotate(w.ref, da);
  const Vec3 df = quat_rotate(w.ref, Vec3(w.kt[0] * ll[0], w.kt[1] * ll[1], w.kt[2] * ll[2]));
  const Vec3 dr = quat_rotate(w.ref, Vec3(w.kr[0] * la[0], w.kr[1] * la[1], w.kr[2] * la[2]));
  double* o1 = df1 + 6 * s.m1;
  for (int i = 0; i < 3; ++i) o1[i] += df[i] * k;
  for (int i = 0; i < 3; ++i) o1[3 + i] += dr[i] * k;
  double* o2 = df2 + 6 * s.m2;
  for (int i = 0; i < 3; ++i) o2[i] -= df[i] * k;
  for (int i = 0; i < 3; ++i) o2[3 + i] -= dr[i] * k;
}

std::array<double, 36> joint_stiffness_block(const JointWork& w) {
  const Mat3 R = quat_to_matrix(w.ref);
  std::array<double, 36> K{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double t = 0, r = 0;
      for (int a = 0; a < 3; ++a) {
        t += R(i, a) * w.kt[a] * R(j, a);
        r += R(i, a) * w.kr[a] * R(j, a);
      }
      K[i * 6 + j] = t;
      K[(3 + i) * 6 + 3 + j] = r;
    }
  return K;
}

}  // namespace sinew::joints
