#include "math/triangle_octree.h"

#include <cmath>
#include <limits>

#include "math/sofa_vec.h"

namespace sinew {

namespace {
inline double max3(double a, double b, double c) {  // std::max({a, b, c})
  double m = a;
  if (m < b) m = b;
  if (m < c) m = c;
  return m;
}
inline double min3(double a, double b, double c) {  // std::min({a, b, c})
  double m = a;
  if (b < m) m = b;
  if (c < m) m = c;
  return m;
}
// SOFA's choose_next: the exit face of a cell is that of the smallest parameter.
inline unsigned choose_next(double x, double y, double z, unsigned a, unsigned b, unsigned c) {
  if (x < y) return x < z ? a : c;
  return y < z ? b : c;
}
}  // namespace

bool ray_triangle_intersection(const Vec3& n0, const Vec3& n1, const Vec3& n2, const Vec3& origin,
                               const Vec3& direction, double& t, double& u, double& v) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  t = u = v = 0;
  const Vec3 e0 = n1 - n0, e1 = n2 - n0;
  const Vec3 pvec = sofa_cross(direction, e1);
  const double det = sofa_dot(e0, pvec);
  if (std::fabs(det) <= eps) return false;
  const double inv_det = 1.0 / det;
  const Vec3 tvec = origin - n0;
  u = sofa_dot(tvec, pvec) * inv_det;
  if (u < 0.0 - eps || u > 1.0 + eps) return false;
  const Vec3 qvec = sofa_cross(tvec, e0);
  v = sofa_dot(direction, qvec) * inv_det;
  if (v < 0.0 - eps || (u + v) > 1.0 + eps) return false;
  t = sofa_dot(e1, qvec) * inv_det;
  return !(t < eps || t != t || v != v || u != u);
}

void TriangleOctree::clear() {
  nodes_.clear();
  inserted_.clear();
  objects_.clear();
  outside_ = 0;
}

void TriangleOctree::build(std::span<const Triangle> triangles, std::span<const Vec3> positions) {
  clear();
  tris_ = triangles;
  x_ = positions;
  Node root;
  root.x = root.y = root.z = -kCubeSize;
  root.size = 2 * kCubeSize;
  nodes_.push_back(root);
  const std::size_t n = positions.size();
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    if (t[0] >= n || t[1] >= n || t[2] >= n) {
      ++outside_;
      continue;
    }
    const Vec3 &p1 = positions[t[0]], &p2 = positions[t[1]], &p3 = positions[t[2]];
    double bb[6];
    for (int k = 0; k < 3; ++k) {
      bb[2 * k] = min3(p1[k], p2[k], p3[k]);
      bb[2 * k + 1] = max3(p1[k], p2[k], p3[k]);
    }
    const double size = max3(std::fabs(bb[1] - bb[0]), std::fabs(bb[3] - bb[2]), std::fabs(bb[5] - bb[4]));
    const bool inside = bb[0] >= -kCubeSize && bb[2] >= -kCubeSize && bb[4] >= -kCubeSize && bb[1] <= kCubeSize &&
                        bb[3] <= kCubeSize && bb[5] <= kCubeSize;
    // A triangle of no extent (or NaN) has no level: SOFA's depth would be
    // infinite (undefined behaviour there); it is left out here.
    if (!inside || !(size > 0)) {
      ++outside_;
      continue;
    }
    // The level whose cells are at least as large as the triangle's box.
    // Depth 30 (cells of 1.5e-6) bounds SOFA's int shift, which overflows below.
    int d1 = static_cast<int>(std::log10(kCubeSize * 2 / size) / std::log10(2.0));
    if (d1 > 30) d1 = 30;
    if (d1 < 0) d1 = 0;
    const double inc = 2 * kCubeSize / static_cast<double>(1 << d1);
    for (double x1 = static_cast<int>((bb[0] + kCubeSize) / inc) * inc - kCubeSize; x1 <= bb[1]; x1 += inc)
      for (double y1 = static_cast<int>((bb[2] + kCubeSize) / inc) * inc - kCubeSize; y1 <= bb[3]; y1 += inc)
        for (double z1 = static_cast<int>((bb[4] + kCubeSize) / inc) * inc - kCubeSize; z1 <= bb[5]; z1 += inc)
          insert(x1, y1, z1, inc, static_cast<int>(i));
  }
  // Triangles per node, in insertion order (a stable counting sort).
  for (const auto& [node, tri] : inserted_) ++nodes_[node].count;
  unsigned offset = 0;
  for (Node& nd : nodes_) {
    nd.first = offset;
    offset += nd.count;
    nd.count = 0;
  }
  objects_.resize(inserted_.size());
  for (const auto& [node, tri] : inserted_) {
    Node& nd = nodes_[node];
    objects_[nd.first + nd.count++] = tri;
  }
}

// Down to the cell of side `inc` holding (x, y, z), creating cells on the way.
void TriangleOctree::insert(double x, double y, double z, double inc, int tri) {
  int k = 0;
  while (inc < nodes_[k].size) {
    const Node& nd = nodes_[k];
    const double size2 = nd.size / 2;
    const int dx = x >= nd.x + size2 ? 1 : 0;
    const int dy = y >= nd.y + size2 ? 1 : 0;
    const int dz = z >= nd.z + size2 ? 1 : 0;
    const int i = dx * 4 + dy * 2 + dz;
    if (nd.child[i] < 0) {
      Node c;
      c.x = nd.x + dx * size2;
      c.y = nd.y + dy * size2;
      c.z = nd.z + dz * size2;
      c.size = size2;
      nodes_[k].is_leaf = false;
      nodes_[k].child[i] = static_cast<int>(nodes_.size());
      nodes_.push_back(c);  // may move the nodes: `nd` is not used after this
    }
    k = nodes_[k].child[i];
  }
  inserted_.emplace_back(k, tri);
}

bool TriangleOctree::hit(int tri, const Ray& ray, double& t, double& u, double& v) const {
  const Triangle& tr = tris_[static_cast<std::size_t>(tri)];
  return ray_triangle_intersection(x_[tr[0]], x_[tr[1]], x_[tr[2]], ray.origin1, ray.direction1, t, u, v);
}

// SOFA's nearestTriangle: the candidate first, then the node's own triangles.
int TriangleOctree::nearest_triangle(int node, int min_index, const Ray& ray, TraceResult& result) const {
  double min_dist, t, u, v;
  if (hit(min_index, ray, t, u, v)) {
    result.u = u;
    result.v = v;
    result.t = min_dist = t;
    result.tid = min_index;
  } else {
    min_dist = 10e8;
    min_index = -1;
  }
  const Node& nd = nodes_[static_cast<std::size_t>(node)];
  for (unsigned k = nd.first; k < nd.first + nd.count; ++k) {
    const int tri = objects_[k];
    if (!hit(tri, ray, t, u, v)) continue;
    if (t < min_dist) {
      result.u = u;
      result.v = v;
      result.t = min_dist = t;
      result.tid = min_index = tri;
    }
  }
  if (min_index < 0) return min_index;
  result.tid = min_index;
  return min_index;
}

int TriangleOctree::trace(Vec3 origin, Vec3 direction, TraceResult& result) const {
  if (nodes_.empty()) return -1;
  Ray ray;
  ray.origin1 = origin;
  ray.direction1 = direction;
  unsigned a = 0, b = 0;
  // Reflect the ray into the positive octant; a zero component marks the axis
  // (SOFA's EPSILON is 0: its parameters are then infinite).
  const unsigned bit[3] = {4, 2, 1};
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0.0) {
      direction[k] = 0.0;
      b |= bit[k];
    } else if (direction[k] < 0.0) {
      origin[k] = -origin[k];
      direction[k] = -direction[k];
      a |= bit[k];
    }
  }
  ray.origin = origin;
  ray.direction = direction;
  const double tx0 = (-kCubeSize - origin[0]) / direction[0], tx1 = (kCubeSize - origin[0]) / direction[0];
  const double ty0 = (-kCubeSize - origin[1]) / direction[1], ty1 = (kCubeSize - origin[1]) / direction[1];
  const double tz0 = (-kCubeSize - origin[2]) / direction[2], tz1 = (kCubeSize - origin[2]) / direction[2];
  if (max3(tx0, ty0, tz0) < min3(tx1, ty1, tz1)) return trace_node(0, ray, tx0, ty0, tz0, tx1, ty1, tz1, a, b, result);
  return -1;
}

int TriangleOctree::trace_node(int node, const Ray& ray, double tx0, double ty0, double tz0, double tx1, double ty1,
                               double tz1, unsigned a, unsigned b, TraceResult& result) const {
  if (tx1 < 0.0 || ty1 < 0.0 || tz1 < 0.0) return -1;
  const Node& nd = nodes_[static_cast<std::size_t>(node)];
  if (nd.is_leaf) return nd.count ? nearest_triangle(node, objects_[nd.first], ray, result) : -1;

  const double x0 = nd.x, y0 = nd.y, z0 = nd.z;
  const double x1 = nd.x + nd.size, y1 = nd.y + nd.size, z1 = nd.z + nd.size;
  constexpr double INF = 1e9;
  const Vec3& o = ray.origin;
  // Mid-cell parameters; along an axis the ray is parallel to, the side of the
  // origin decides (SOFA compares the reflected origin with the cell's centre).
  const double txm = (b & 4) ? (o[0] < 0.5 * (x0 + x1) ? +INF : -INF) : 0.5 * (tx0 + tx1);
  const double tym = (b & 2) ? (o[1] < 0.5 * (y0 + y1) ? +INF : -INF) : 0.5 * (ty0 + ty1);
  const double tzm = (b & 1) ? (o[2] < 0.5 * (z0 + z1) ? +INF : -INF) : 0.5 * (tz0 + tz1);

  // The entry octant.
  unsigned current = 0;
  if (tx0 > ty0) {
    if (tx0 > tz0) {
      if (tym < tx0) current |= 2;
      if (tzm < tx0) current |= 1;
    } else {
      if (txm < tz0) current |= 4;
      if (tym < tz0) current |= 2;
    }
  } else {
    if (ty0 > tz0) {
      if (txm < ty0) current |= 4;
      if (tzm < ty0) current |= 1;
    } else {
      if (txm < tz0) current |= 4;
      if (tym < tz0) current |= 2;
    }
  }

  constexpr unsigned END = 8;
  // One child: its parameter box, then the next octant along the ray.
  auto visit = [&](unsigned octant, double cx0, double cy0, double cz0, double cx1, double cy1, double cz1) {
    const int c = nd.child[octant ^ a];
    if (c < 0) return -1;
    return trace_node(c, ray, cx0, cy0, cz0, cx1, cy1, cz1, a, b, result);
  };
  while (true) {
    int idx = -1;
    switch (current) {
      case 0:
        idx = visit(0, tx0, ty0, tz0, txm, tym, tzm);
        current = choose_next(txm, tym, tzm, 4, 2, 1);
        break;
      case 1:
        idx = visit(1, tx0, ty0, tzm, txm, tym, tz1);
        current = choose_next(txm, tym, tz1, 5, 3, END);
        break;
      case 2:
        idx = visit(2, tx0, tym, tz0, txm, ty1, tzm);
        current = choose_next(txm, ty1, tzm, 6, END, 3);
        break;
      case 3:
        idx = visit(3, tx0, tym, tzm, txm, ty1, tz1);
        current = choose_next(txm, ty1, tz1, 7, END, END);
        break;
      case 4:
        idx = visit(4, txm, ty0, tz0, tx1, tym, tzm);
        current = choose_next(tx1, tym, tzm, END, 6, 5);
        break;
      case 5:
        idx = visit(5, txm, ty0, tzm, tx1, tym, tz1);
        current = choose_next(tx1, tym, tz1, END, 7, END);
        break;
      case 6:
        idx = visit(6, txm, tym, tz0, tx1, ty1, tzm);
        current = choose_next(tx1, ty1, tzm, END, END, 7);
        break;
      case 7:
        idx = visit(7, txm, tym, tzm, tx1, ty1, tz1);
        current = END;
        break;
      default:  // END: the ray left the cell; the cell's own triangles remain
        return nd.count ? nearest_triangle(node, objects_[nd.first], ray, result) : -1;
    }
    if (idx != -1) return nearest_triangle(node, idx, ray, result);
  }
}

}  // namespace sinew
