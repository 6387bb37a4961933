// Collision elements as the intersection tests see them: plain values copied
// out of the collision models by the narrow phase (positions already read,
// the owning model's skin `cd` = its contactDistance, and the model's element
// count, which decides some contact ids: spec/interaction.md §2).
#pragma once

#include <array>
#include <cstddef>

#include "math/types.h"

namespace sinew {

// Triangle feature flags (spec/interaction.md §2.6): the vertices and edges a
// triangle "owns" (it is the first triangle around them), and boundary edges.
enum TriangleFlag : int {
  kFlagP1 = 1 << 0,
  kFlagP2 = 1 << 1,
  kFlagP3 = 1 << 2,
  kFlagE23 = 1 << 3,  // edge opposite vertex 0
  kFlagE31 = 1 << 4,  // edge opposite vertex 1
  kFlagE12 = 1 << 5,  // edge opposite vertex 2
  kFlagBE23 = 1 << 6,
  kFlagBE31 = 1 << 7,
  kFlagBE12 = 1 << 8,
  kFlagPoints = kFlagP1 | kFlagP2 | kFlagP3,
  kFlagEdges = kFlagE23 | kFlagE31 | kFlagE12,
};

// What every element carries besides its geometry.
struct ElemInfo {
  unsigned index = 0;           // element index in its model
  std::size_t model_size = 0;   // number of elements of its model
  double cd = 0;                // the model's contactDistance (skin) [length]
  const void* model = nullptr;  // identity of the owning model (same-model tests)
};

struct PointElem {
  Vec3 p;
  ElemInfo info;
  Vec3 n = Vec3::Zero();  // vertex normal (PointCollisionModel computeNormals), else zero
};

struct LineElem {
  Vec3 a, b;                    // vertex 0 and vertex 1 of the edge
  std::array<unsigned, 2> v{};  // their point indices
  ElemInfo info;
};

struct TriangleElem {
  Vec3 a, b, c;                 // vertices 0, 1, 2 (topology order)
  Vec3 normal;                  // stored unit normal (frozen for non-moving models)
  std::array<unsigned, 3> v{};  // their point indices
  int flags = 0;                // TriangleFlag bits
  ElemInfo info;
};

struct TetrahedronElem {
  std::array<Vec3, 4> p;        // vertices 0..3 (topology order)
  std::array<unsigned, 4> v{};  // their point indices
  ElemInfo info;
};

// An oriented box (OBBCollisionModel): a Rigid3d frame and three half-extents.
// A point is inside when c + a·axis[0] + b·axis[1] + d·axis[2] with |a| ≤ ext[0], …
struct ObbElem {
  Vec3 c;                    // centre (the frame's translation)
  std::array<Vec3, 3> axis;  // the frame's x, y, z axes in world coordinates (unit)
  Vec3 ext;                  // half-extents along the axes [length]
  Vec3 v;                    // linear velocity of the frame [length/time]
  ElemInfo info;
};

struct SphereElem {
  Vec3 c;              // centre (translation of a rigid sphere)
  double r = 0;        // radius [length]
  bool rigid = false;  // Rigid3d sphere: contact point c − n·r by normal n; Vec3d: c
  ElemInfo info;
  // SOFA's getContactPointByNormal(n).
  Vec3 contact_point(const Vec3& n) const { return rigid ? Vec3(c - n * r) : c; }
};

}  // namespace sinew
