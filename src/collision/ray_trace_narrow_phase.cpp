#include "collision/ray_trace_narrow_phase.h"

#include "collision/intersect/elements.h"
#include "collision/model/triangle_octree_collision_model.h"
#include "core/registry.h"
#include "math/sofa_vec.h"

namespace sinew {

void RayTraceNarrowPhase::detect(const std::vector<ModelPair>& pairs, const Intersection& /*method*/) {
  for (PairOutputs& p : outputs_) p.outputs.clear();
  job_models_.clear();
  for (const ModelPair& pair : pairs) {
    if (!dynamic_cast<TriangleOctreeCollisionModel*>(pair.first) ||
        !dynamic_cast<TriangleOctreeCollisionModel*>(pair.second)) {
      if (!warned_)
        msg_warning("only pairs of TriangleOctreeCollisionModels are tested: " + pair.first->describe() + " and " +
                    pair.second->describe() + " (and any other such pair) collide with nothing");
      warned_ = true;
      continue;
    }
    job_models_.push_back(pair);
  }
  // Output entries are created first: an insertion moves the entries after it.
  for (const ModelPair& p : job_models_) {
    output_index(p.first, p.second);
    output_index(p.second, p.first);
  }
  jobs_.clear();
  for (const ModelPair& p : job_models_) jobs_.emplace_back(output_index(p.first, p.second), output_index(p.second, p.first));
  for (std::size_t k = 0; k < job_models_.size(); ++k) {
    const auto& a = static_cast<const TriangleOctreeCollisionModel&>(*job_models_[k].first);
    const auto& b = static_cast<const TriangleOctreeCollisionModel&>(*job_models_[k].second);
    find_pairs_volume(a, b, outputs_[jobs_[k].first].outputs);
    find_pairs_volume(b, a, outputs_[jobs_[k].second].outputs);
  }
}

void RayTraceNarrowPhase::find_pairs_volume(const TriangleOctreeCollisionModel& m1,
                                            const TriangleOctreeCollisionModel& m2,
                                            std::vector<DetectionOutput>& out) {
  if (m1.empty() || m2.empty()) return;
  const TriangleOctree& octree1 = m1.octree();
  const TriangleOctree& octree2 = m2.octree();
  const Aabb& box2 = m2.surface_box();
  const std::vector<Vec3>& normals1 = m1.vertex_normals();
  const std::size_t n_points1 = m1.point_count();
  for (unsigned j = 0; j < m1.size(); ++j) {
    const Triangle& tri1 = m1.triangle(j);
    // A triangle naming points the state does not have (reported by the model) casts nothing.
    if (tri1[0] >= n_points1 || tri1[1] >= n_points1 || tri1[2] >= n_points1) continue;
    const int flags = m1.flags(j);
    unsigned vertex[3];
    int n_points = 0;
    for (int k = 0; k < 3; ++k)
      if (flags & (kFlagP1 << k)) vertex[n_points++] = tri1[k];
    for (int t = 0; t < n_points; ++t) {
      const Vec3& point = m1.point(vertex[t]);
      if (point[0] < box2.min[0] || point[0] > box2.max[0] || point[1] < box2.min[1] || point[1] > box2.max[1] ||
          point[2] < box2.min[2] || point[2] > box2.max[2])
        continue;
      const Vec3& normal = normals1[vertex[t]];
      // The first triangle of the other surface inward from the vertex, facing it …
      TriangleOctree::TraceResult res, res2;
      const int hit2 = octree2.trace(point, -normal, res);
      if (hit2 == -1) continue;
      if (sofa_dot(m1.normal(j), m2.normal(static_cast<unsigned>(hit2))) > 0) continue;
      // … met before the ray leaves this surface (no exit: not a closed surface).
      const int hit1 = octree1.trace(point, -normal, res2);
      if (hit1 == -1 || res2.t < res.t) continue;
      if (sofa_dot(m1.normal(j), m1.normal(static_cast<unsigned>(hit1))) > 0) continue;
      const Triangle& tri2 = m2.triangle(static_cast<unsigned>(hit2));
      const double w1 = 1.0 - res.u - res.v;
      Vec3 q;
      for (int c = 0; c < 3; ++c)
        q[c] = m2.point(tri2[0])[c] * w1 + m2.point(tri2[1])[c] * res.u + m2.point(tri2[2])[c] * res.v;
      DetectionOutput& d = out.emplace_back();
      d.elem1 = j;
      d.elem2 = static_cast<unsigned>(hit2);
      d.point1 = point;
      d.point2 = q;
      d.normal = normal;
      d.value = -res.t;
      d.id = static_cast<std::int64_t>(j) * 3 + t;
    }
  }
}

void register_ray_trace_narrow_phase(Registry& r) {
  ComponentInfo info;
  info.name = "RayTraceNarrowPhase";
  info.category = "Collision/Detection";
  info.description =
      "narrow phase casting rays from the vertices of TriangleOctreeCollisionModels into the other surface "
      "(volume contacts between closed surfaces)";
  info.create = creator<RayTraceNarrowPhase>();
  r.add(std::move(info));
}

}  // namespace sinew
