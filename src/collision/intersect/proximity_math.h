// Arithmetic shared by the element tests, written in the operation order of
// SOFA's Vec (dot products summed x, then y, then z) so that distances and
// barycentric coordinates round like SOFA's. Internal to src/collision/intersect.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "collision/detection_output.h"
#include "collision/intersect/elements.h"
#include "math/types.h"

namespace sinew::intersect_detail {

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm2(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(norm2(a)); }

// Contact id "index of the element of the larger model": SOFA compares with a
// strict `>`, so on equal model sizes the id is element 2's index.
inline std::int64_t larger_model_index(const ElemInfo& i1, const ElemInfo& i2) {
  return i1.model_size > i2.model_size ? i1.index : i2.index;
}

// Appends a zero-initialised output and returns it.
inline DetectionOutput& append(std::vector<DetectionOutput>& out, const ElemInfo& i1, const ElemInfo& i2,
                               std::int64_t id) {
  DetectionOutput& d = out.emplace_back();
  d.elem1 = i1.index;
  d.elem2 = i2.index;
  d.id = id;
  return d;
}

// MinProximity's normalisation: value := |v|, normal := v/|v|, or (1,0,0)
// when the two points coincide (SOFA also logs a warning there).
inline void set_normal_guarded(DetectionOutput& d, const Vec3& v) {
  d.value = norm(v);
  if (d.value > 1e-15)
    d.normal = v / d.value;
  else
    d.normal = Vec3(1, 0, 0);
}

// A MinProximity output along v (from the point on element 1 to the point on
// element 2, as computed for the alarm test): value |v| − contact, normal
// v/|v| (guarded). The caller sets the two points.
inline DetectionOutput& append_along(std::vector<DetectionOutput>& out, const ElemInfo& i1, const ElemInfo& i2,
                                     std::int64_t id, const Vec3& v, double contact) {
  DetectionOutput& d = append(out, i1, i2, id);
  set_normal_guarded(d, v);
  d.value -= contact;
  return d;
}

}  // namespace sinew::intersect_detail
