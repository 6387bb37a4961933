#include "engine/generate/random_point_distribution_in_surface.h"

#include <ctime>

#include "core/registry.h"
#include "math/sofa_vec.h"
#include "math/triangle_octree.h"

namespace sinew {

RandomPointDistributionInSurface::RandomPointDistributionInSurface()
    : vertices(this, "vertices", FlatVec{}, "vertices of the surface", "Inputs", "length"),
      in_points(this, "inPoints", FlatVec{}, "points inside the surface", "Outputs", "length"),
      out_points(this, "outPoints", FlatVec{}, "points drawn and rejected (outside or too close)", "Outputs",
                 "length") {
  add_input(&triangles);
  add_input(&vertices);
  add_output(&in_points);
}

void RandomPointDistributionInSurface::init() {
  if (number_of_tests.get() % 2 == 0) {
    msg_warning("even number of tests: one more is added");
    number_of_tests.set(number_of_tests.get() + 1);
  }
  if (random_seed.get() == 0) random_seed.set(static_cast<unsigned>(std::time(nullptr)));
  rng_.seed_with(static_cast<long>(random_seed.get()));
  // SOFA draws the directions once, right after seeding.
  directions_.clear();
  for (unsigned i = 0; i < number_of_tests.get(); ++i) {
    Vec3 d;
    for (int c = 0; c < 3; ++c) d[c] = rng_.uniform(-1.0, 1.0);
    directions_.push_back(d);
  }
  // SOFA's safe limit n⁴ in unsigned 32-bit arithmetic (it wraps for n ≥ 256).
  const std::uint32_t n = number_of_in_points.get();
  safe_limit_ = n * n * n * n;
  set_dirty();
}

void RandomPointDistributionInSurface::do_update() {
  const FlatVec& v = vertices.get();
  const std::vector<Triangle>& tris = triangles.get();
  if (tris.size() <= 1 || v.size() <= 1) {
    msg_error("the surface needs more than one vertex and more than one triangle");
    return;
  }
  if (v.width != 3) {
    msg_error("vertices must be 3D points");
    return;
  }
  std::vector<Vec3> x(v.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = Vec3(v.data[3 * i], v.data[3 * i + 1], v.data[3 * i + 2]);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (unsigned k : tris[i])
      if (k >= x.size()) {
        msg_error("triangle " + std::to_string(i) + " names point " + std::to_string(k) + " of " +
                  std::to_string(x.size()));
        return;
      }
  TriangleOctree octree;
  octree.build(tris, x);
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double d2 = min_distance.get() * min_distance.get();
  std::vector<Vec3> in, out;
  auto inside = [&](const Vec3& p) {
    unsigned votes = 0;
    for (const Vec3& d : directions_) {
      TriangleOctree::TraceResult r;
      if (octree.trace(p, d, r) < 0) continue;
      const Triangle& t = tris[static_cast<std::size_t>(r.tid)];
      Vec3 nrm = sofa_cross(x[t[1]] - x[t[0]], x[t[2]] - x[t[0]]);
      const double len = sofa_norm(nrm);
      if (len > std::numeric_limits<double>::epsilon()) nrm /= len;  // SOFA's normalize()
      if (sofa_dot(d, nrm) > 0.0) ++votes;
    }
    return votes == directions_.size();
  };
  auto far_enough = [&](const Vec3& p) {
    for (const Vec3& q : in) {
      const Vec3 e = p - q;
      if (sofa_dot(e, e) < d2) return false;
    }
    return true;
  };
  std::uint32_t tries = 0;
  while (in.size() < number_of_in_points.get() && tries < safe_limit_) {
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = rng_.uniform(lo[c], hi[c]);
    if (inside(p) && far_enough(p))
      in.push_back(p);
    else
      out.push_back(p);
    ++tries;
  }
  if (tries == safe_limit_)
    msg_error("stopped after " + std::to_string(tries) + " draws with " + std::to_string(in.size()) + " of " +
              std::to_string(number_of_in_points.get()) + " points inside (is the surface closed?)");
  auto flat = [](const std::vector<Vec3>& pts) {
    FlatVec f;
    f.width = 3;
    f.data.reserve(3 * pts.size());
    for (const Vec3& p : pts) f.data.insert(f.data.end(), {p[0], p[1], p[2]});
    return f;
  };
  in_points.set(flat(in));
  out_points.set(flat(out));
}

void register_random_point_distribution_in_surface(Registry& r) {
  ComponentInfo info;
  info.name = "RandomPointDistributionInSurface";
  info.category = "Engine/Generate";
  info.description = "random points inside a closed triangle surface (ray-cast inside test)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<RandomPointDistributionInSurface>();
  r.add(std::move(info));
}

}  // namespace sinew
