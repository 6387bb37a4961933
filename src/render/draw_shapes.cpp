#include "render/draw_shapes.h"

#include <Eigen/Geometry>

#include <cmath>

namespace sinew::render {

namespace {

void push(std::vector<float>& v, const Vec3& p) {
  for (int c = 0; c < 3; ++c) v.push_back(static_cast<float>(p[c]));
}

void push_color(Batch& b, const std::array<float, 4>* color, std::size_t vertices) {
  if (!color) return;
  for (std::size_t i = 0; i < vertices; ++i) b.colors.insert(b.colors.end(), color->begin(), color->end());
}

}  // namespace

void append_sphere(Batch& b, const Vec3& centre, double radius, const std::array<float, 4>* color) {
  constexpr int kLat = 8, kLon = 12;
  const auto base = static_cast<unsigned>(b.positions.size() / 3);
  for (int la = 0; la <= kLat; ++la) {
    const double th = M_PI * la / kLat;
    for (int lo = 0; lo <= kLon; ++lo) {
      const double ph = 2 * M_PI * lo / kLon;
      const Vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      push(b.positions, centre + radius * n);
      push(b.normals, n);
    }
  }
  push_color(b, color, (kLat + 1) * (kLon + 1));
  for (int la = 0; la < kLat; ++la)
    for (int lo = 0; lo < kLon; ++lo) {
      const unsigned a = base + la * (kLon + 1) + lo, c = a + kLon + 1;
      b.indices.insert(b.indices.end(), {a, c, a + 1, a + 1, c, c + 1});
    }
}

void append_cone(Batch& b, const Vec3& a, const Vec3& tip, double ra, double rb, const std::array<float, 4>* color) {
  constexpr int kSides = 12;
  const Vec3 axis = tip - a;
  const double len = axis.norm();
  if (!(len > 0) || !std::isfinite(len)) return;
  const Vec3 w = axis / len;
  // Two directions across the axis.
  const Vec3 helper = std::abs(w.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = w.cross(helper).normalized(), v = w.cross(u);
  // The side's normal leans along the axis by the slope (ra − rb) / len.
  const double slope = (ra - rb) / len;
  const auto base = static_cast<unsigned>(b.positions.size() / 3);
  for (int k = 0; k <= kSides; ++k) {
    const double t = 2 * M_PI * k / kSides;
    const Vec3 radial = std::cos(t) * u + std::sin(t) * v;
    const Vec3 n = (radial + slope * w).normalized();
    push(b.positions, a + ra * radial);
    push(b.normals, n);
    push(b.positions, tip + rb * radial);
    push(b.normals, n);
  }
  push_color(b, color, 2 * (kSides + 1));
  for (int k = 0; k < kSides; ++k) {
    const unsigned i = base + 2 * k;
    b.indices.insert(b.indices.end(), {i, i + 2, i + 1, i + 1, i + 2, i + 3});
  }
}

void append_frame(Batch& b, const Vec3& origin, const Mat3& axes, double length) {
  static const std::array<float, 4> kAxisColor[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  for (int k = 0; k < 3; ++k) {
    const Vec3 dir = axes.col(k);
    const Vec3 end = origin + length * dir;
    append_cone(b, origin, end, length / 10, length / 10, &kAxisColor[k]);
    append_cone(b, end, end + (length / 5) * dir, length / 5, 0.0, &kAxisColor[k]);
  }
}

void append_box_edges(Batch& b, const Vec3& lo, const Vec3& hi) {
  auto corner = [&](int i) { return Vec3(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]); };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit))
        for (const Vec3& p : {corner(i), corner(i | bit)})
          for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(p[c]));
}

void append_box(Batch& b, const Vec3& lo, const Vec3& hi, const std::array<float, 4>& color) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 n = Vec3::Zero();
      n[axis] = side ? 1.0 : -1.0;
      const auto base = static_cast<unsigned>(b.positions.size() / 3);
      for (int k = 0; k < 4; ++k) {
        Vec3 p;
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
        p[v] = (k >= 2) ? hi[v] : lo[v];
        push(b.positions, p);
        push(b.normals, n);
      }
      push_color(b, &color, 4);
      b.indices.insert(b.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
}

void append_scene_frame(Batch& b, int style) {
  static const std::array<float, 4> kAxis[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  static const std::array<float, 4> kGrey{0.5f, 0.5f, 0.5f, 1}, kDark{0.25f, 0.25f, 0.25f, 1};
  if (style == 2) {
    constexpr double s = 0.25;
    append_box(b, Vec3(-s, -s, -s), Vec3(s, s, s), kDark);
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k);
      append_cone(b, s * e, 3 * s * e, 0.0, s, &kAxis[k]);
      append_cone(b, -s * e, -3 * s * e, 0.0, s, &kGrey);
    }
    return;
  }
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    if (style == 1) {
      append_cone(b, Vec3::Zero(), e, 0.05, 0.05, &kAxis[k]);
    } else {
      append_cone(b, Vec3::Zero(), 0.8 * e, 0.05, 0.05, &kAxis[k]);
      append_cone(b, 0.8 * e, e, 0.125, 0.0, &kAxis[k]);
    }
  }
}

}  // namespace sinew::render
