#include "forcefield/spring/gear_spring.h"

#include <cmath>

#include "forcefield/spring/spring_text.h"
#include "math/sofa_vec.h"

namespace sinew::gears {

namespace {

using spring_text::to_double;
using spring_text::to_unsigned;
using spring_text::Tokens;

// Rotation vector taking unit vector u onto v (SOFA's getVectorAngle).
Vec3 vector_angle(const Vec3& u, const Vec3& v) {
  Vec3 w = sofa_cross(u, v);
  const double nw = sofa_norm(w), dt = sofa_dot(u, v);
  if (nw != 0) w *= std::atan2(nw, dt) / nw;
  return w;
}

Quat orientation(const double* x) { return Quat::from(x + 3); }
Vec3 column(const Mat3& m, unsigned j) { return Vec3(m(0, j), m(1, j), m(2, j)); }

}  // namespace

std::string parse_gear_springs(std::string_view text, std::vector<GearSpring>& out) {
  out.clear();
  Tokens in{text};
  GearSpring s;  // reused from one spring to the next (carries KS_T, KS_R, KD, RATIO over)
  std::string_view tok;
  while (in.next(tok)) {
    const std::string where = "spring " + std::to_string(out.size());
    if (tok != "BEGIN_SPRING") return where + ": expected BEGIN_SPRING, found '" + std::string(tok) + "'";
    s.axis = {0, 0};
    std::string_view a, b, c, d;
    if (!in.next(a) || !in.next(b) || !in.next(c) || !in.next(d) || !to_unsigned(a, s.p1) || !to_unsigned(b, s.m1) ||
        !to_unsigned(c, s.p2) || !to_unsigned(d, s.m2))
      return where + ": BEGIN_SPRING must be followed by four frame indices (pivot1 gear1 pivot2 gear2)";
    auto numbers = [&](std::string_view key, std::initializer_list<double*> slots) {
      return spring_text::read_numbers(in, where, key, slots);
    };
    bool closed = false;
    while (in.next(tok)) {
      std::string err;
      if (tok == "END_SPRING") {
        closed = true;
        break;
      } else if (tok == "AXIS") {
        for (unsigned& ax : s.axis) {
          std::string_view t;
          if (!in.next(t) || !to_unsigned(t, ax) || ax > 2) {
            err = where + ": AXIS needs two axis numbers 0, 1 or 2 (x, y, z), one per gear";
            break;
          }
        }
      } else if (tok == "KS_T") {
        err = numbers(tok, {&s.hard_trans});
      } else if (tok == "KS_R") {
        err = numbers(tok, {&s.soft_rot, &s.hard_rot});
      } else if (tok == "KD") {
        err = numbers(tok, {&s.kd});
      } else if (tok == "RATIO") {
        err = numbers(tok, {&s.ratio});
        if (err.empty() && !(std::isfinite(s.ratio) && s.ratio != 0))
          err = where + ": RATIO must be a finite number other than 0";
      } else {
        err = where + ": unknown keyword '" + std::string(tok) + "' (AXIS, KS_T, KS_R, KD, RATIO, END_SPRING)";
      }
      if (!err.empty()) return err;
    }
    if (!closed) return where + ": missing END_SPRING";
    out.push_back(s);
  }
  return "";
}

double angle_around_axis(const double* a, const double* b, unsigned axis) {
  const Mat3 Ma = quat_to_matrix(orientation(a)), Mb = quat_to_matrix(orientation(b));
  const Vec3 W = column(Ma, axis);
  double angle = 0.0;
  int count = 0;
  for (unsigned j = 0; j < 3; ++j) {
    if (j == axis) continue;
    ++count;
    const Vec3 w = vector_angle(column(Ma, j), column(Mb, j));
    if (sofa_dot(w, W) < 0)
      angle -= sofa_norm(w);
    else
      angle += sofa_norm(w);
  }
  return angle / count;
}

void init_gear_work(const GearSpring& s, const double* x1, const double* x2, GearWork& w) {
  if (s.p1 == s.m1) {
    w.angle1 = w.previous_angle1 = 0.0;
    std::copy(x1 + 7 * s.p1, x1 + 7 * s.p1 + 7, w.x1);
  } else {
    w.angle1 = w.previous_angle1 = angle_around_axis(x1 + 7 * s.p1, x1 + 7 * s.m1, s.axis[0]);
  }
  if (s.p2 == s.m2) {
    w.angle2 = w.previous_angle2 = 0.0;
    std::copy(x2 + 7 * s.p2, x2 + 7 * s.p2 + 7, w.x2);
  } else {
    w.angle2 = w.previous_angle2 = angle_around_axis(x2 + 7 * s.p2, x2 + 7 * s.m2, s.axis[1]);
  }
}

void add_gear_spring_force(const GearSpring& s, GearWork& w, const double* x1, const double* v1, double* f1,
                           const double* x2, const double* v2, double* f2) {
  const double* c1 = x1 + 7 * s.m1;  // the gears
  const double* c2 = x2 + 7 * s.m2;
  double dv1[6], dv2[6];  // pivot velocity minus gear velocity
  for (int i = 0; i < 6; ++i) dv1[i] = -v1[6 * s.m1 + i], dv2[i] = -v2[6 * s.m2 + i];
  // The pivots: another frame of the state (kept for the tangent), or the gear's initial frame.
  if (s.m1 != s.p1) {
    for (int i = 0; i < 6; ++i) dv1[i] += v1[6 * s.p1 + i];
    std::copy(x1 + 7 * s.p1, x1 + 7 * s.p1 + 7, w.x1);
  }
  if (s.m2 != s.p2) {
    for (int i = 0; i < 6; ++i) dv2[i] += v2[6 * s.p2 + i];
    std::copy(x2 + 7 * s.p2, x2 + 7 * s.p2 + 7, w.x2);
  }
  const double* cp1 = w.x1;
  const double* cp2 = w.x2;

  // Each gear held on its pivot: translation, and rotation of the free axis onto the pivot's.
  auto hold = [&](const double* cc, const double* cp, unsigned axis, const double* dv, double* fg, double* fp) {
    const Vec3 ft = Vec3(cp[0] - cc[0], cp[1] - cc[1], cp[2] - cc[2]) * s.hard_trans +
                    Vec3(dv[0], dv[1], dv[2]) * s.kd;
    const Vec3 u = column(quat_to_matrix(orientation(cc)), axis), v = column(quat_to_matrix(orientation(cp)), axis);
    const Vec3 fr = vector_angle(u, v) * s.hard_rot + Vec3(dv[3], dv[4], dv[5]) * s.kd;
    for (int i = 0; i < 3; ++i) fg[i] += ft[i], fg[3 + i] += fr[i];
    if (fp)
      for (int i = 0; i < 3; ++i) fp[i] -= ft[i], fp[3 + i] -= fr[i];
  };
  hold(c1, cp1, s.axis[0], dv1, f1 + 6 * s.m1, s.m1 != s.p1 ? f1 + 6 * s.p1 : nullptr);
  hold(c2, cp2, s.axis[1], dv2, f2 + 6 * s.m2, s.m2 != s.p2 ? f2 + 6 * s.p2 : nullptr);

  // The gear: axes in world coordinates, angles accumulated since the start.
  const Vec3 axis1 = column(quat_to_matrix(orientation(c1)), s.axis[0]);
  const Vec3 axis2 = column(quat_to_matrix(orientation(c2)), s.axis[1]);
  double a1 = angle_around_axis(cp1, c1, s.axis[0]);
  double a2 = angle_around_axis(cp2, c2, s.axis[1]);
  // SOFA unwraps with M_2_PI, which is 2/π, not 2π: kept, as the results depend on it.
  constexpr double kPi = 3.14159265358979323846, kStep = 2.0 / kPi;
  while (a1 - w.previous_angle1 > kPi) a1 -= kStep;
  while (a1 - w.previous_angle1 < -kPi) a1 += kStep;
  while (a2 - w.previous_angle2 > kPi) a2 -= kStep;
  while (a2 - w.previous_angle2 < -kPi) a2 += kStep;
  w.angle1 += a1 - w.previous_angle1;
  w.previous_angle1 = a1;
  w.angle2 += a2 - w.previous_angle2;
  w.previous_angle2 = a2;
  const double f = (-w.angle1 * s.ratio - w.angle2) * s.soft_rot;  // equal and opposite at the contact point
  w.torque = f;
  for (int i = 0; i < 3; ++i) f1[6 * s.m1 + 3 + i] += axis1[i] * f;
  for (int i = 0; i < 3; ++i) f2[6 * s.m2 + 3 + i] += axis2[i] * f / s.ratio;
}

void add_gear_spring_dforce(const GearSpring& s, const GearWork& w, const double* dx1, double* df1,
                            const double* dx2, double* df2, double k) {
  double d1[6], d2[6];
  for (int i = 0; i < 6; ++i) d1[i] = -dx1[6 * s.m1 + i], d2[i] = -dx2[6 * s.m2 + i];
  if (s.m1 != s.p1)
    for (int i = 0; i < 6; ++i) d1[i] += dx1[6 * s.p1 + i];
  if (s.m2 != s.p2)
    for (int i = 0; i < 6; ++i) d2[i] += dx2[6 * s.p2 + i];
  const Quat q1 = orientation(w.x1), q2 = orientation(w.x2);
  // Hard stiffnesses, none about the free axis (in the pivot's frame).
  auto hold = [&](const Quat& q, unsigned axis, const double* d, double* dfg, double* dfp) {
    Vec3 kr(s.hard_rot, s.hard_rot, s.hard_rot);
    kr[axis] = 0;
    const Vec3 dft = Vec3(d[0], d[1], d[2]) * s.hard_trans;
    const Vec3 local = quat_inverse_rotate(q, Vec3(d[3], d[4], d[5]));
    const Vec3 dfr = quat_rotate(q, Vec3(kr[0] * local[0], kr[1] * local[1], kr[2] * local[2]));
    for (int i = 0; i < 3; ++i) dfg[i] += dft[i] * k, dfg[3 + i] += dfr[i] * k;
    if (dfp)
      for (int i = 0; i < 3; ++i) dfp[i] -= dft[i] * k, dfp[3 + i] -= dfr[i] * k;
  };
  hold(q1, s.axis[0], d1, df1 + 6 * s.m1, s.m1 != s.p1 ? df1 + 6 * s.p1 : nullptr);
  hold(q2, s.axis[1], d2, df2 + 6 * s.m2, s.m2 != s.p2 ? df2 + 6 * s.p2 : nullptr);
  // The gear coupling, through the gears' rotations about their axes.
  const double* w1 = dx1 + 6 * s.m1 + 3;
  const double* w2 = dx2 + 6 * s.m2 + 3;
  const double dangle1 = quat_inverse_rotate(q1, Vec3(w1[0], w1[1], w1[2]))[s.axis[0]];
  const double dangle2 = quat_inverse_rotate(q2, Vec3(w2[0], w2[1], w2[2]))[s.axis[1]];
  Vec3 kr1 = Vec3::Zero(), kr2 = Vec3::Zero();
  kr1[s.axis[0]] = -s.soft_rot * (dangle1 * s.ratio + dangle2);
  kr2[s.axis[1]] = -s.soft_rot * (dangle1 + dangle2 / s.ratio);
  const Vec3 t1 = quat_rotate(q1, kr1), t2 = quat_rotate(q2, kr2);
  for (int i = 0; i < 3; ++i) df1[6 * s.m1 + 3 + i] += t1[i] * k;
  for (int i = 0; i < 3; ++i) df2[6 * s.m2 + 3 + i] += t2[i] * k;
}

}  // namespace sinew::gears
