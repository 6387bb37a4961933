// Separating-axis queries of oriented boxes, in the formulation SOFA's
// CollisionOBBCapsule plugin took from Geometric Tools (IntrOBBOBB,
// IntrTriangleOBB, IntrSphereOBB and their utilities). Each primitive is
// projected onto candidate axes; the axis of largest separation (or least
// overlap) wins, and the features that realise its interval ends (corner,
// edge, face: the "configuration") give the contact points. Operation order
// and tolerances are SOFA's, so that the same contacts come out.
#include "collision/intersect/obb_tests.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include "collision/intersect/proximity_math.h"
#include "math/sofa_vec.h"

namespace sinew::obb {

namespace {

constexpr double kTol = 1e-6;           // IntrUtil::ZERO_TOLERANCE
constexpr double kSqTol = kTol * kTol;  // IntrUtil::SQ_ZERO_TOLERANCE

// SOFA's Vec arithmetic and the output helpers shared by the element tests.
using intersect_detail::append;
using intersect_detail::dot;
using intersect_detail::larger_model_index;
using intersect_detail::norm2;

// Rescaled unless already within 1e-12 of unit length (IntrUtil::normalize).
void normalize_loose(Vec3& v) {
  const double n2 = norm2(v);
  if (n2 < 1 - kSqTol || n2 > 1 + kSqTol) sofa_normalize(v);
}

// How a primitive's vertices project onto the ends of its interval
// (IntrConfiguration): segments m2/m11, triangles m3…m111, boxes m44 (a face
// at each end), m2_2 (an edge at each end), m1_1 (a corner at each end).
enum Map { m2, m11, m3, m21, m12, m111, m44, m2_2, m1_1 };
// Which side of primitive 0 primitive 1 lies on along the winning axis.
enum Side { kLeft, kRight, kNone };

struct Config {
  int map = m1_1;
  int index[8] = {};  // vertex order: boxes by corner code (bit k: + along axis k), triangles 0..2
  double min = 0, max = 0;
};

// What a query found (SOFA's Intersector): the separating axis (from primitive
// 0 towards 1 once oriented), a point on each, the largest separation found.
struct Found {
  Vec3 axis = Vec3::Zero();
  Vec3 p0 = Vec3::Zero(), p1 = Vec3::Zero();
  double sep = -std::numeric_limits<double>::max();
  int side = kNone;
  bool colliding = false;
  Config cfg0, cfg1;
};

// Corner `code` of a box centred at c (bit 2, 1, 0: + along axis 2, 1, 0),
// summed axis 2 first as SOFA's getPointFromIndex.
Vec3 corner(int code, const Vec3& c, const ObbElem& b) {
  Vec3 p = c;
  if (code & 4) p += b.ext[2] * b.axis[2];
  else p -= b.ext[2] * b.axis[2];
  if (code & 2) p += b.ext[1] * b.axis[1];
  else p -= b.ext[1] * b.axis[1];
  if (code & 1) p += b.ext[0] * b.axis[0];
  else p -= b.ext[0] * b.axis[0];
  return p;
}
Vec3 corner(int code, const ObbElem& b) { return corner(code, b.c, b); }

// Projection of a box onto `axis` (IntrConfigManager<Box>::init). Axes within
// 1e-6 of perpendicular to box axes make faces or edges the interval's ends; the
// corner codes are listed so that four of them walk around the face.
Config box_config(const Vec3& axis, const ObbElem& box) {
  Config cfg;
  const double axes[3] = {dot(axis, box.axis[0]), dot(axis, box.axis[1]), dot(axis, box.axis[2])};
  const double abs_axes[3] = {std::fabs(axes[0]), std::fabs(axes[1]), std::fabs(axes[2])};
  auto set = [&](std::initializer_list<std::pair<int, int>> entries) {
    for (const auto& [slot, code] : entries) cfg.index[slot] = code;
  };
  double extent;
  if (abs_axes[0] < kTol) {
    if (abs_axes[1] < kTol) {
      cfg.map = m44;  // faces normal to axis 2
      extent = abs_axes[2] * box.ext[2];
      if (axes[2] > 0) set({{0, 0}, {1, 1}, {2, 3}, {3, 2}, {4, 6}, {5, 7}, {6, 5}, {7, 4}});
      else set({{0, 6}, {1, 7}, {2, 5}, {3, 4}, {4, 0}, {5, 1}, {6, 3}, {7, 2}});
    } else if (abs_axes[2] < kTol) {
      cfg.map = m44;  // faces normal to axis 1
      extent = abs_axes[1] * box.ext[1];
      if (axes[1] > 0) set({{0, 4}, {1, 5}, {2, 1}, {3, 0}, {4, 2}, {5, 3}, {6, 7}, {7, 6}});
      else set({{0, 2}, {1, 3}, {2, 7}, {3, 6}, {4, 4}, {5, 5}, {6, 1}, {7, 0}});
    } else {
      cfg.map = m2_2;  // edges along axis 0
      extent = abs_axes[1] * box.ext[1] + abs_axes[2] * box.ext[2];
      if (axes[1] > 0) {
        if (axes[2] > 0) set({{0, 0}, {1, 1}, {6, 6}, {7, 7}});
        else set({{0, 4}, {1, 5}, {6, 2}, {7, 3}});
      } else {
        if (axes[2] > 0) set({{0, 2}, {1, 3}, {6, 4}, {7, 5}});
        else set({{0, 6}, {1, 7}, {6, 0}, {7, 1}});
      }
    }
  } else if (abs_axes[1] < kTol) {
    if (abs_axes[2] < kTol) {
      cfg.map = m44;  // faces normal to axis 0
      extent = abs_axes[0] * box.ext[0];
      if (axes[0] > 0) set({{0, 0}, {1, 2}, {2, 6}, {3, 4}, {4, 5}, {5, 7}, {6, 3}, {7, 1}});
      else set({{4, 0}, {5, 2}, {6, 6}, {7, 4}, {0, 5}, {1, 7}, {2, 3}, {3, 1}});
    } else {
      cfg.map = m2_2;  // edges along axis 1
      extent = abs_axes[0] * box.ext[0] + abs_axes[2] * box.ext[2];
      if (axes[0] > 0) {
        if (axes[2] > 0) set({{0, 0}, {1, 2}, {6, 5}, {7, 7}});
        else set({{0, 4}, {1, 6}, {6, 1}, {7, 3}});
      } else {
        if (axes[2] > 0) set({{0, 1}, {1, 3}, {6, 4}, {7, 6}});
        else set({{0, 5}, {1, 7}, {6, 0}, {7, 2}});
      }
    }
  } else if (abs_axes[2] < kTol) {
    cfg.map = m2_2;  // edges along axis 2
    extent = abs_axes[0] * box.ext[0] + abs_axes[1] * box.ext[1];
    if (axes[0] > 0) {
      if (axes[1] > 0) set({{0, 0}, {1, 4}, {6, 3}, {7, 7}});
      else set({{0, 2}, {1, 6}, {6, 1}, {7, 5}});
    } else {
      if (axes[1] > 0) set({{0, 1}, {1, 5}, {6, 2}, {7, 6}});
      else set({{0, 3}, {1, 7}, {6, 0}, {7, 4}});
    }
  } else {
    cfg.map = m1_1;  // a corner at each end; opposite corners' codes add up to 7
    extent = abs_axes[0] * box.ext[0] + abs_axes[1] * box.ext[1] + abs_axes[2] * box.ext[2];
    cfg.index[0] = (axes[0] > 0.0 ? 0 : 1) + (axes[1] > 0.0 ? 0 : 2) + (axes[2] > 0.0 ? 0 : 4);
    cfg.index[7] = 7 - cfg.index[0];
  }
  const double origin = dot(axis, box.c);
  cfg.min = origin - extent;
  cfg.max = origin + extent;
  return cfg;
}

bool tol_inf(double a, double b) { return a < b + kTol; }
bool tol_nequal(double a, double b) { return a < b - kTol || b < a - kTol; }

// Projection of a triangle onto `axis` (IntrConfigManager<Triangle>::init): its
// vertices sorted, ties within 1e-6 merged into edges or the face.
Config triangle_config(const Vec3& axis, const TriangleElem& t) {
  Config cfg;
  const double d0 = dot(axis, t.a), d1 = dot(axis, t.b), d2 = dot(axis, t.c);
  auto order = [&](int i0, int i1, int i2) {
    cfg.index[0] = i0, cfg.index[1] = i1, cfg.index[2] = i2;
  };
  if (tol_inf(d0, d1)) {
    if (tol_inf(d1, d2)) {  // d0 <= d1 <= d2
      if (tol_nequal(d0, d1)) cfg.map = tol_nequal(d1, d2) ? m111 : m12;
      else cfg.map = tol_nequal(d1, d2) ? m21 : m3;
      order(0, 1, 2);
      cfg.min = d0, cfg.max = d2;
    } else if (tol_inf(d0, d2)) {  // d0 <= d2 < d1
      if (tol_nequal(d0, d2)) cfg.map = m111, order(0, 2, 1);
      else cfg.map = m21, order(2, 0, 1);
      cfg.min = d0, cfg.max = d1;
    } else {  // d2 < d0 <= d1
      cfg.map = tol_nequal(d0, d1) ? m111 : m12;
      order(2, 0, 1);
      cfg.min = d2, cfg.max = d1;
    }
  } else if (tol_inf(d2, d1)) {  // d2 <= d1 < d0
    if (tol_nequal(d2, d1)) cfg.map = m111, order(2, 1, 0);
    else cfg.map = m21, order(1, 2, 0);
    cfg.min = d2, cfg.max = d0;
  } else if (tol_inf(d2, d0)) {  // d1 < d2 <= d0
    cfg.map = tol_nequal(d2, d0) ? m111 : m12;
    order(1, 2, 0);
    cfg.min = d1, cfg.max = d0;
  } else {  // d1 < d0 < d2
    cfg.map = m111;
    order(1, 0, 2);
    cfg.min = d1, cfg.max = d2;
  }
  return cfg;
}

// One candidate axis (IntrConfigManager::Find): false when the two intervals
// are `dmax` or more apart (no contact); otherwise keeps the axis in `f` if its
// separation (negative: overlap) is the largest so far. Returns whether it did
// through `modified`.
bool test_axis(const Config& c0, const Config& c1, double dmax, Found& f, bool& modified) {
  modified = false;
  auto keep = [&](double d, int side) {
    if (d > f.sep) {
      f.sep = d;
      f.side = side;
      f.cfg0 = c0;
      f.cfg1 = c1;
      modified = true;
    }
  };
  if (c1.max < c0.min) {  // 1 left of 0
    const double d = c0.min - c1.max;
    if (d >= dmax) return false;
    keep(d, kLeft);
  } else if (c0.max < c1.min) {  // 1 right of 0
    const double d = c1.min - c0.max;
    if (d >= dmax) return false;
    keep(d, kRight);
  } else {  // overlapping: the side of the midpoints
    const double mid0 = (c0.min + c0.max) / 2.0, mid1 = (c1.min + c1.max) / 2.0;
    if (mid1 < mid0) keep(c0.min - c1.max, kLeft);
    else keep(c1.min - c0.max, kRight);
  }
  return true;
}

// The polygon P (quantity vertices, ≤ 8) clipped to the side n·x ≥ c of a
// plane, with a tolerance of |c|·1e-6 towards keeping (ClipConvexPolygonAgainstPlane).
void clip(const Vec3& normal, double constant, int& quantity, Vec3* P) {
  int positive = 0, negative = 0, p_index = -1;
  const int n = quantity;
  double test[8];
  for (int i = 0; i < n; ++i) {
    test[i] = dot(normal, P[i]) - constant + std::fabs(constant) * kTol;
    if (test[i] >= 0) {
      ++positive;
      if (p_index < 0) p_index = i;
    } else {
      ++negative;
    }
  }
  if (quantity == 2) {  // a segment: one end moves onto the plane
    if (positive == 0) {
      quantity = 0;
    } else if (negative > 0) {
      const int c = p_index == 0 ? 1 : 0;
      const double t = test[p_index] / (test[p_index] - test[c]);
      P[c] = P[p_index] + t * (P[c] - P[p_index]);
    }
    return;
  }
  if (positive == 0) {
    quantity = 0;
    return;
  }
  if (negative == 0) return;
  Vec3 cv[8];
  int q = 0, cur, prv;
  auto cut = [&](int a, int b) {
    const double t = test[a] / (test[a] - test[b]);
    cv[q++] = P[a] + t * (P[b] - P[a]);
  };
  if (p_index > 0) {
    cur = p_index;
    cut(cur, cur - 1);
    while (cur < n && test[cur] >= 0) cv[q++] = P[cur++];
    if (cur < n) {
      prv = cur - 1;
    } else {
      cur = 0;
      prv = n - 1;
    }
    cut(cur, prv);
  } else {
    cur = 0;
    while (cur < n && test[cur] >= 0) cv[q++] = P[cur++];
    cut(cur, cur - 1);
    while (cur < n && test[cur] < 0) ++cur;
    if (cur < n) {
      cut(cur, cur - 1);
      while (cur < n && test[cur] >= 0) cv[q++] = P[cur++];
    } else {
      cut(0, n - 1);
    }
  }
  std::copy(cv, cv + q, P);
  quantity = q;
}

// `first` (count points, the first `count` of P) clipped by the four sides of a rectangle.
void clip_to_rectangle(const Vec3* first, int count, const Vec3 rect[4], int& quantity, Vec3* P) {
  quantity = count;
  std::copy(first, first + count, P);
  for (int i0 = 3, i1 = 0; i1 < 4; i0 = i1++) {
    const Vec3 normal = rect[i1] - rect[i0];
    clip(normal, dot(normal, rect[i0]), quantity, P);
  }
}

// A segment clipped by the three sides of a triangle (ColinearSegmentTriangle).
void clip_to_triangle(const Vec3 seg[2], const Vec3 tri[3], int& quantity, Vec3* P) {
  quantity = 2;
  P[0] = seg[0], P[1] = seg[1];
  const Vec3 side[3] = {tri[1] - tri[0], tri[2] - tri[1], tri[0] - tri[2]};
  const Vec3 normal = sofa_cross(side[0], side[1]);
  for (int i = 0; i < 3; ++i) {
    const Vec3 inward = sofa_cross(normal, side[i]);
    clip(inward, dot(inward, tri[i]), quantity, P);
  }
}

// Mean of the points, each moved by velocity·time (projectIntPoints).
Vec3 mean_moved(const Vec3& velocity, double time, const Vec3* points, int n) {
  Vec3 sum = Vec3::Zero();
  const Vec3 v0 = velocity * time;
  for (int i = 0; i < n; ++i) sum += points[i] + v0;
  sum /= n;
  return sum;
}

// Closest points of segments [p0,p1] and [q0,q1] (segNearestPoints). Nearly
// parallel segments (|det| ≤ 1e-6) take the middle of their overlap.
void segment_nearest(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& P, Vec3& Q) {
  const Vec3 AB = p1 - p0, CD = q1 - q0, AC = q0 - p0;
  const double a00 = dot(AB, AB), a11 = dot(CD, CD), a01 = dot(-CD, AB);
  const double b0 = dot(AB, AC), b1 = dot(-CD, AC);
  const double det = a00 * a11 - a01 * a01;
  const double ab2 = norm2(AB), cd2 = norm2(CD);
  double alpha = 0.5, beta = 0.5;
  if (det < -kTol || det > kTol) {
    alpha = (b0 * a11 - b1 * a01) / det;
    beta = (b1 * a00 - b0 * a01) / det;
  } else {
    const Vec3 AD = q1 - p0, CB = p1 - q0;
    const double c_proj = b0 / ab2, d_proj = dot(AB, AD) / ab2;
    const double a_proj = b1 / cd2, b_proj = dot(CD, CB) / cd2;
    if (c_proj >= 0 && c_proj <= 1) {
      if (d_proj > 1) alpha = (1.0 + c_proj) / 2.0, beta = b_proj / 2.0;
      else if (d_proj < 0) alpha = c_proj / 2.0, beta = (1 + a_proj) / 2.0;
      else alpha = (c_proj + d_proj) / 2.0, beta = 0.5;
    } else if (d_proj >= 0 && d_proj <= 1) {
      if (c_proj < 0) alpha = d_proj / 2.0, beta = (1 + a_proj) / 2.0;
      else alpha = (1 + d_proj) / 2.0, beta = b_proj / 2.0;
    } else if (c_proj * d_proj < 0) {
      alpha = 0.5, beta = (a_proj + b_proj) / 2.0;
    } else {
      alpha = c_proj < 0 ? 0 : 1;
      beta = a_proj < 0 ? 0 : 1;
    }
    P = p0 + AB * alpha;
    Q = q0 + CD * beta;
    return;
  }
  if (alpha < 0) alpha = 0, beta = dot(CD, p0 - q0) / cd2;
  else if (alpha > 1) alpha = 1, beta = dot(CD, p1 - q0) / cd2;
  if (beta < 0) beta = 0, alpha = dot(AB, q0 - p0) / ab2;
  else if (beta > 1) beta = 1, alpha = dot(AB, q1 - p0) / ab2;
  alpha = std::clamp(alpha, 0.0, 1.0);
  P = p0 + AB * alpha;
  Q = q0 + CD * beta;
}
void segment_nearest(const Vec3 p[2], const Vec3 q[2], Vec3& P, Vec3& Q) { segment_nearest(p[0], p[1], q[0], q[1], P, Q); }

// Closest points between the sides of polygon `face` (n vertices) and a segment (faceSegNearestPoints).
void face_segment_nearest(const Vec3* face, int n, const Vec3 seg[2], Vec3& on_face, Vec3& on_seg) {
  double best = std::numeric_limits<double>::max();
  for (int j = 0; j < n; ++j) {
    const Vec3 side[2] = {face[j], j < n - 1 ? face[j + 1] : face[0]};
    Vec3 a, b;
    segment_nearest(side, seg, a, b);
    const double d = norm2(a - b);
    if (d < best) best = d, on_face = a, on_seg = b;
  }
}

// Closest points between the sides of two polygons (facesNearestPoints); ties keep the first.
void faces_nearest(const Vec3* f0, int n0, const Vec3* f1, int n1, Vec3& on0, Vec3& on1) {
  double best = std::numeric_limits<double>::max();
  for (int i = 0; i < n0; ++i) {
    const Vec3 s0[2] = {f0[i], i < n0 - 1 ? f0[i + 1] : f0[0]};
    for (int j = 0; j < n1; ++j) {
      const Vec3 s1[2] = {f1[j], j < n1 - 1 ? f1[j + 1] : f1[0]};
      Vec3 a, b;
      segment_nearest(s0, s1, a, b);
      const double d = norm2(a - b);
      if (best > d) best = d, on0 = a, on1 = b;
    }
  }
}

// ---------------------------------------------------------------- box–box

// Contact points of two boxes from the winning axis' configurations
// (FindContactSet<Box,Box>). `t` is the separation along `axis` (negative:
// overlap); box 1 is moved by it onto box 0 for the face cases.
void box_box_contact(const ObbElem& b0, const ObbElem& b1, const Vec3& axis, Found& f) {
  const double t = f.sep;
  const int* i0 = f.cfg0.index;
  const int* i1 = f.cfg1.index;
  const int m0 = f.cfg0.map, m1 = f.cfg1.map;
  Vec3 P[8];
  int quantity;
  // The side of each box that faces the other: box 1's low end and box 0's high
  // end when box 1 is on the right, the reverse on the left.
  const bool left = f.side == kLeft;
  const int lo0 = left ? 0 : 4, lo1 = left ? 4 : 0;  // face slots
  const int e0 = left ? 0 : 6, e1 = left ? 6 : 0;    // edge slots
  const double s = left ? 1.0 : -1.0;                // box 1 moved by s·t·axis
  if (m0 == m1_1) {
    f.p0 = corner(left ? i0[0] : i0[7], b0);
    f.p1 = left ? Vec3(f.p0 - axis * t) : Vec3(f.p0 + t * axis);
    return;
  }
  if (m1 == m1_1) {
    f.p1 = corner(left ? i1[7] : i1[0], b1);
    f.p0 = left ? Vec3(f.p1 + axis * t) : Vec3(f.p1 - t * axis);
    return;
  }
  const Vec3 moved_c = left ? Vec3(b1.c + t * axis) : Vec3(b1.c - t * axis);
  if (m0 == m2_2) {
    const Vec3 edge0[2] = {corner(i0[e0], b0), corner(i0[e0 + 1], b0)};
    if (m1 == m2_2) {
      const Vec3 edge1[2] = {corner(i1[e1], b1), corner(i1[e1 + 1], b1)};
      segment_nearest(edge0, edge1, f.p0, f.p1);
      return;
    }
    const Vec3 face1[4] = {corner(i1[lo1], moved_c, b1), corner(i1[lo1 + 1], moved_c, b1),
                           corner(i1[lo1 + 2], moved_c, b1), corner(i1[lo1 + 3], moved_c, b1)};
    clip_to_rectangle(edge0, 2, face1, quantity, P);
    if (quantity != 0) {
      f.p1 = mean_moved(-s * axis, t, P, quantity);
      f.p0 = left ? Vec3(f.p1 + axis * t) : Vec3(f.p1 - axis * t);
    } else {
      face_segment_nearest(face1, 4, edge0, f.p1, f.p0);
      if (left) f.p1 -= t * axis;
      else f.p1 += axis * t;
    }
    return;
  }
  // Box 0 touches by a face.
  const Vec3 face0[4] = {corner(i0[lo0 == 0 ? 0 : 4], b0), corner(i0[lo0 == 0 ? 1 : 5], b0),
                         corner(i0[lo0 == 0 ? 2 : 6], b0), corner(i0[lo0 == 0 ? 3 : 7], b0)};
  if (m1 == m2_2) {
    const Vec3 edge1[2] = {corner(i1[e1], moved_c, b1), corner(i1[e1 + 1], moved_c, b1)};
    clip_to_rectangle(edge1, 2, face0, quantity, P);
    if (quantity != 0) {
      f.p1 = mean_moved(-s * axis, t, P, quantity);
      f.p0 = left ? Vec3(f.p1 + axis * t) : Vec3(f.p1 - axis * t);
    } else {
      face_segment_nearest(face0, 4, edge1, f.p0, f.p1);
      if (left) f.p1 -= t * axis;
      else f.p1 += axis * t;
    }
    return;
  }
  const Vec3 face1[4] = {corner(i1[lo1], moved_c, b1), corner(i1[lo1 + 1], moved_c, b1),
                         corner(i1[lo1 + 2], moved_c, b1), corner(i1[lo1 + 3], moved_c, b1)};
  clip_to_rectangle(face0, 4, face1, quantity, P);
  if (quantity == 0) {
    faces_nearest(face0, 4, face1, 4, f.p0, f.p1);
    if (left) f.p1 -= t * axis;
    else f.p1 += t * axis;
  } else {
    f.p1 = mean_moved(-s * axis, t, P, quantity);
    f.p0 = left ? Vec3(f.p1 + axis * t) : Vec3(f.p1 - axis * t);
  }
}

// TIntrOBBOBB::Find: the 3 + 3 face normals, the 9 edge crossings (a parallel
// pair ends the search there: the faces decided), then the relative velocity
// crossed with each box's axes. False when one axis separates by `dmax` or more.
bool find_box_box(const ObbElem& b0, const ObbElem& b1, double dmax, Found& f) {
  bool modified;
  auto try_axis = [&](const Vec3& axis) {
    if (!test_axis(box_config(axis, b0), box_config(axis, b1), dmax, f, modified)) return false;
    if (modified) f.axis = axis;
    return true;
  };
  auto finish = [&] {
    box_box_contact(b0, b1, f.axis, f);
    if (f.side == kLeft) f.axis *= -1.0;
  };
  for (int i = 0; i < 3; ++i)
    if (!try_axis(b0.axis[i])) return false;
  for (int i = 0; i < 3; ++i)
    if (!try_axis(b1.axis[i])) return false;
  for (int i0 = 0; i0 < 3; ++i0)
    for (int i1 = 0; i1 < 3; ++i1) {
      Vec3 axis = sofa_cross(b0.axis[i0], b1.axis[i1]);
      if (norm2(axis) <= kTol) {
        finish();
        if (f.sep < 0) f.colliding = true;
        return true;
      }
      normalize_loose(axis);
      if (!try_axis(axis)) return false;
    }
  const Vec3 rel_v = b1.v - b0.v;
  for (const ObbElem* b : {&b0, &b1})
    for (int i = 0; i < 3; ++i) {
      Vec3 axis = sofa_cross(rel_v, b->axis[i]);
      if (norm2(axis) > kSqTol) {
        normalize_loose(axis);
        if (!try_axis(axis)) return false;
      }
    }
  if (f.sep <= 0) {
    if (f.side == kNone) return false;
    f.colliding = true;
  }
  finish();
  return true;
}

// ------------------------------------------------------------ triangle–box

// A point outside the box moved onto its surface: clamped per axis; a point
// inside goes to the face of smallest relative depth. Kept from SOFA: that face
// is placed by a world coordinate (index of the box axis), right only for boxes
// aligned with the world axes; the sign is the last negative one seen.
void project_on_box(Vec3& point, const ObbElem& box) {
  int min_ind = -1;
  bool neg = false, inside = true;
  double diff = std::numeric_limits<double>::max();
  const Vec3 centred = point - box.c;
  point = box.c;
  for (int i = 0; i < 3; ++i) {
    double ci = dot(box.axis[i], centred);
    if (ci < -box.ext[i] - kTol) {
      inside = false;
      ci = -box.ext[i];
    } else if (ci > box.ext[i] + kTol) {
      inside = false;
      ci = box.ext[i];
    } else {
      const double d = std::fabs(std::fabs(ci) - box.ext[i]) / box.ext[i];
      if (d < diff) {
        diff = d;
        min_ind = i;
        if (ci < 0.0) neg = true;
      }
    }
    point += ci * box.axis[i];
  }
  if (inside) point[min_ind] = neg ? box.c[min_ind] - box.ext[min_ind] : box.c[min_ind] + box.ext[min_ind];
}

// Closest point of triangle (t0, t1, t2) to pt, written into pt (Geometric Tools' region scheme).
void project_on_triangle(Vec3& pt, const Vec3& t0, const Vec3& t1, const Vec3& t2) {
  const Vec3 diff = t0 - pt, edge0 = t1 - t0, edge1 = t2 - t0;
  const double a00 = norm2(edge0), a01 = dot(edge0, edge1), a11 = norm2(edge1);
  const double b0 = dot(diff, edge0), b1 = dot(diff, edge1);
  const double det = std::fabs(a00 * a11 - a01 * a01);
  double s = a01 * b1 - a11 * b0, t = a01 * b0 - a00 * b1;
  if (s + t <= det) {
    if (s < 0) {
      if (t < 0) {  // region 4
        if (b0 < 0) {
          t = 0;
          s = -b0 >= a00 ? 1 : -b0 / a00;
        } else {
          s = 0;
          t = b1 >= 0 ? 0 : -b1 >= a11 ? 1 : -b1 / a11;
        }
      } else {  // region 3
        s = 0;
        t = b1 >= 0 ? 0 : -b1 >= a11 ? 1 : -b1 / a11;
      }
    } else if (t < 0) {  // region 5
      t = 0;
      s = b0 >= 0 ? 0 : -b0 >= a00 ? 1 : -b0 / a00;
    } else {  // region 0: interior
      const double inv = 1.0 / det;
      s *= inv;
      t *= inv;
    }
  } else if (s < 0) {  // region 2
    const double tmp0 = a01 + b0, tmp1 = a11 + b1;
    if (tmp1 > tmp0) {
      const double numer = tmp1 - tmp0, denom = a00 - 2.0 * a01 + a11;
      if (numer >= denom) s = 1, t = 0;
      else s = numer / denom, t = 1 - s;
    } else {
      s = 0;
      t = tmp1 <= 0 ? 1 : b1 >= 0 ? 0 : -b1 / a11;
    }
  } else if (t < 0) {  // region 6
    const double tmp0 = a01 + b1, tmp1 = a00 + b0;
    if (tmp1 > tmp0) {
      const double numer = tmp1 - tmp0, denom = a00 - 2.0 * a01 + a11;
      if (numer >= denom) t = 1, s = 0;
      else t = numer / denom, s = 1 - t;
    } else {
      t = 0;
      s = tmp1 <= 0 ? 1 : b0 >= 0 ? 0 : -b0 / a00;
    }
  } else {  // region 1
    const double numer = a11 + b1 - a01 - b0;
    if (numer <= 0) {
      s = 0, t = 1;
    } else {
      const double denom = a00 - 2.0 * a01 + a11;
      if (numer >= denom) s = 1, t = 0;
      else s = numer / denom, t = 1 - s;
    }
  }
  pt = t0 + s * edge0 + t * edge1;
}

// Closest points between the triangle's sides and a segment (triSegNearestPoints).
void triangle_segment_nearest(const Vec3 tri[3], const Vec3 seg[2], Vec3& on_tri, Vec3& on_seg) {
  face_segment_nearest(tri, 3, seg, on_tri, on_seg);
}

// The closest pair of vertices (triangle, face); two pairs within 1e-6 of the
// same distance give their midpoints (triFaceNearestPoints).
void triangle_face_nearest(const Vec3 tri[3], const Vec3* face, int n, Vec3& on_tri, Vec3& on_face) {
  double min1 = std::numeric_limits<double>::max(), min2 = min1;
  int f1 = -1, f2 = -1, s1 = -1, s2 = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < n; ++j) {
      const double d = norm2(tri[i] - face[j]);
      if (min1 > d) {
        min2 = min1, f2 = f1, s2 = s1;
        min1 = d, f1 = i, s1 = j;
      } else if (min2 > d) {
        f2 = i, s2 = j, min2 = d;
      }
    }
  if (f1 < 0) return;  // no finite distance (the boxes of non-finite elements are skipped before)
  if (f2 >= 0 && min2 > min1 - kTol && min2 < min1 + kTol) {
    on_tri = (tri[f1] + tri[f2]) / 2.0;
    on_face = (face[s1] + face[s2]) / 2.0;
  } else {
    on_tri = tri[f1];
    on_face = face[s1];
  }
}

// Contact points of a triangle and a box (FindContactSet<Triangle,Box>).
void triangle_box_contact(const TriangleElem& tr, const ObbElem& box, const Vec3& axis, Found& f) {
  const double t = f.sep;
  const int* ti = f.cfg0.index;
  const int* bi = f.cfg1.index;
  const int tm = f.cfg0.map, bm = f.cfg1.map;
  const Vec3 tri[3] = {tr.a, tr.b, tr.c};
  Vec3 P[8];
  int quantity;
  if (f.side == kLeft) {  // the box on the triangle's low side
    if (tm == m111 || tm == m12) {
      f.p0 = tri[ti[0]];
      f.p1 = f.p0;
      project_on_box(f.p1, box);
    } else if (bm == m1_1) {
      f.p1 = corner(bi[7], box);
      f.p0 = f.p1;
      project_on_triangle(f.p0, tr.a, tr.b, tr.c);
    } else if (tm == m21) {
      if (bm == m2_2) {
        const Vec3 tseg[2] = {tri[ti[0]], tri[ti[1]]};
        const Vec3 bseg[2] = {corner(bi[6], box), corner(bi[7], box)};
        segment_nearest(tseg, bseg, f.p0, f.p1);
      } else {
        const Vec3 moved[3] = {tri[0] - t * axis, tri[1] - t * axis, tri[2] - t * axis};
        const Vec3 tseg[2] = {moved[ti[0]], moved[ti[1]]};
        const Vec3 face[4] = {corner(bi[4], box), corner(bi[5], box), corner(bi[6], box), corner(bi[7], box)};
        clip_to_rectangle(tseg, 2, face, quantity, P);
        if (quantity != 0) {
          f.p0 = mean_moved(axis, t, P, quantity);
          f.p1 = f.p0 - axis * t;
        } else {
          face_segment_nearest(face, 4, tseg, f.p1, f.p0);
          f.p0 += t * axis;
        }
      }
    } else {  // the triangle's face
      const Vec3 moved[3] = {tri[0] - t * axis, tri[1] - t * axis, tri[2] - t * axis};
      if (bm == m2_2) {
        const Vec3 bseg[2] = {corner(bi[6], box), corner(bi[7], box)};
        clip_to_triangle(bseg, moved, quantity, P);
        if (quantity != 0) {
          f.p0 = mean_moved(axis, t, P, quantity);
          f.p1 = f.p0 - t * axis;
        } else {
          triangle_segment_nearest(tri, bseg, f.p0, f.p1);
        }
      } else {
        const Vec3 face[4] = {corner(bi[4], box), corner(bi[5], box), corner(bi[6], box), corner(bi[7], box)};
        clip_to_rectangle(moved, 3, face, quantity, P);
        if (quantity != 0) {
          f.p0 = mean_moved(axis, t, P, quantity);
          f.p1 = f.p0 - t * axis;
        } else {
          triangle_face_nearest(tri, face, 4, f.p0, f.p1);
        }
      }
    }
    return;
  }
  // The box on the triangle's high side.
  if (tm == m111 || tm == m21) {
    f.p0 = tri[ti[2]];
    f.p1 = f.p0;
    project_on_box(f.p1, box);
  } else if (bm == m1_1) {
    f.p1 = corner(bi[0], box);
    f.p0 = f.p1;
    project_on_triangle(f.p0, tr.a, tr.b, tr.c);
  } else if (tm == m12) {
    if (bm == m2_2) {
      const Vec3 tseg[2] = {tri[ti[1]], tri[ti[2]]};
      const Vec3 bseg[2] = {corner(bi[0], box), corner(bi[1], box)};
      segment_nearest(tseg, bseg, f.p0, f.p1);
    } else {
      const Vec3 moved[3] = {tri[0] + t * axis, tri[1] + t * axis, tri[2] + t * axis};
      const Vec3 tseg[2] = {moved[ti[1]], moved[ti[2]]};
      const Vec3 face[4] = {corner(bi[0], box), corner(bi[1], box), corner(bi[2], box), corner(bi[3], box)};
      clip_to_rectangle(tseg, 2, face, quantity, P);
      if (quantity != 0) {
        f.p0 = mean_moved(-axis, t, P, quantity);
        f.p1 = f.p0 + t * axis;
      } else {
        face_segment_nearest(face, 4, tseg, f.p1, f.p0);
        f.p0 -= t * axis;
      }
    }
  } else {  // the triangle's face
    const Vec3 moved[3] = {tri[0] + t * axis, tri[1] + t * axis, tri[2] + t * axis};
    if (bm == m2_2) {
      const Vec3 bseg[2] = {corner(bi[0], box), corner(bi[1], box)};
      clip_to_triangle(bseg, moved, quantity, P);
      if (quantity != 0) {
        f.p0 = mean_moved(-axis, t, P, quantity);
        f.p1 = f.p0 + t * axis;
      } else {
        triangle_segment_nearest(tri, bseg, f.p0, f.p1);
      }
    } else {
      const Vec3 face[4] = {corner(bi[0], box), corner(bi[1], box), corner(bi[2], box), corner(bi[3], box)};
      clip_to_rectangle(moved, 3, face, quantity, P);
      if (quantity != 0) {
        f.p0 = mean_moved(-axis, t, P, quantity);
        f.p1 = f.p0 + t * axis;
      } else {
        triangle_face_nearest(tri, face, 4, f.p0, f.p1);
      }
    }
  }
}

// TIntrTriangleOBB::Find: the triangle's normal, the box's axes, then the
// owned edges crossed with the box axes (or, when a box axis is along the
// normal, with the normal). A contact point on a vertex the triangle does not
// own is dropped (another triangle reports it).
bool find_triangle_box(const TriangleElem& tr, const ObbElem& box, double dmax, Found& f) {
  bool modified;
  auto try_axis = [&](const Vec3& axis) {
    if (!test_axis(triangle_config(axis, tr), box_config(axis, box), dmax, f, modified)) return false;
    if (modified) f.axis = axis;
    return true;
  };
  const Vec3 edge[3] = {tr.b - tr.a, tr.c - tr.b, tr.a - tr.c};
  const int flags = tr.flags;
  const int owned[3] = {kFlagE12, kFlagE23, kFlagE31};
  if (!try_axis(tr.normal)) return false;
  int coplanar = -1;
  for (int i = 0; i < 3; ++i) {
    if (!try_axis(box.axis[i])) return false;
    const double nda = dot(tr.normal, box.axis[i]);
    if (std::fabs(1.0 - nda * nda) < kTol) coplanar = i;
  }
  if (coplanar == -1) {
    for (int i = 0; i < 3; ++i)
      for (int e = 0; e < 3; ++e) {
        if (!(flags & owned[e])) continue;
        Vec3 axis = sofa_cross(edge[e], box.axis[i]);
        if (norm2(axis) > kTol) {
          normalize_loose(axis);
          if (!try_axis(axis)) return false;
        }
      }
  } else {
    for (int e = 0; e < 3; ++e) {
      if (!(flags & owned[e])) continue;
      Vec3 axis = sofa_cross(edge[e], tr.normal);
      normalize_loose(axis);
      if (!try_axis(axis)) return false;
    }
  }
  if (f.side == kNone) return false;
  triangle_box_contact(tr, box, f.axis, f);
  auto at = [&](const Vec3& v) { return norm2(f.p0 - v) < kSqTol; };
  if (!(flags & kFlagP1) && at(tr.a)) return false;
  if (!(flags & kFlagP2) && at(tr.b)) return false;
  if (!(flags & kFlagP3) && at(tr.c)) return false;
  if (f.side == kLeft) f.axis *= -1.0;
  return true;
}

}  // namespace

int obb_obb(double alarm, double contact, const ObbElem& e1, const ObbElem& e2, std::vector<DetectionOutput>& out) {
  Found f;
  if (!find_box_box(e1, e2, alarm, f)) return 0;
  const Vec3 d01 = f.p1 - f.p0;
  const double dist2 = norm2(d01);
  if (!f.colliding && dist2 > alarm * alarm) return 0;
  // SOFA's strict `>` on model sizes: on a tie the id is box 2's index.
  DetectionOutput& d = append(out, e1.info, e2.info, larger_model_index(e1.info, e2.info));
  // The axis when the points lie along it (the separating axis is unit), else the points' direction.
  if (norm2(sofa_cross(d01, f.axis)) < kTol) {
    d.normal = f.axis;
  } else {
    d.normal = d01;
    sofa_normalize(d.normal);
  }
  d.point1 = f.p0;
  d.point2 = f.p1;
  d.value = f.colliding ? -std::sqrt(dist2) - contact : std::sqrt(dist2) - contact;
  return 1;
}

int triangle_obb(double alarm, double contact, const TriangleElem& e1, const ObbElem& e2,
                 std::vector<DetectionOutput>& out) {
  Found f;
  if (!find_triangle_box(e1, e2, alarm, f)) return 0;
  // SOFA's triangle–box query never marks the pair as colliding: overlapping
  // pairs farther than the alarm apart are dropped, the others get +distance.
  const double dist2 = norm2(f.p0 - f.p1);
  if (dist2 > alarm * alarm) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e1.info.index);
  d.normal = f.axis;
  d.point1 = f.p0;
  d.point2 = f.p1;
  d.value = std::sqrt(dist2) - contact;
  return 1;
}

int sphere_obb(double alarm, double contact, const SphereElem& e1, const ObbElem& e2, std::vector<DetectionOutput>& out) {
  // TIntrSphereOBB::Find: the centre clamped into the box.
  bool colliding = true;
  Vec3 on_box = e2.c, on_sphere = e1.c;
  const Vec3 centred = on_sphere - on_box;
  for (int i = 0; i < 3; ++i) {
    double ci = dot(e2.axis[i], centred);
    if (ci < -e2.ext[i]) {
      colliding = false;
      ci = -e2.ext[i];
    } else if (ci > e2.ext[i]) {
      colliding = false;
      ci = e2.ext[i];
    }
    on_box += ci * e2.axis[i];
  }
  Vec3 axis;
  if (colliding) {
    // Inside: the axis of largest |coordinate / extent|, pointing from the sphere to the box centre.
    int k = 0;
    double alpha = dot(e2.axis[0], centred) / e2.ext[0];
    for (int i = 1; i < 3; ++i) {
      const double a = dot(e2.axis[i], centred) / e2.ext[i];
      if (std::fabs(a) > std::fabs(alpha)) alpha = a, k = i;
    }
    axis = e2.axis[k];
    if (dot(axis, e2.c - e1.c) < 0) axis *= -1.0;
    on_sphere = e1.c + e1.r * axis;
    on_box = alpha > 0 ? Vec3(e2.c + e2.ext[k] * e2.axis[k] + centred) : Vec3(e2.c - e2.ext[k] * e2.axis[k] + centred);
    // Kept from SOFA: the world coordinate k, not the box's axis k (right for aligned boxes only).
    on_box[k] -= centred[k];
  } else {
    axis = on_box - on_sphere;
    normalize_loose(axis);
    on_sphere += e1.r * axis;
    if (dot(on_box - on_sphere, centred) > 0) colliding = true;
  }
  const double dist = std::fabs(dot(axis, on_sphere - on_box));
  if (!colliding && dist > alarm) return 0;
  DetectionOutput& d = append(out, e1.info, e2.info, e1.info.index);
  d.normal = axis;
  // A Vec3d sphere's contact point is its centre; a rigid sphere's the surface point.
  d.point1 = e1.rigid ? on_sphere : e1.c;
  d.point2 = on_box;
  d.value = colliding ? -dist - contact : dist - contact;
  return 1;
}

}  // namespace sinew::obb
