// CubeTopology: the surface grid of a box (points, edges and quads), an
// nx × ny × nz lattice between `min` and `max` without its interior points
// unless `internalPoints` (spec/mechanics.md §5.3).
#pragma once

#include "topology/mesh_topology.h"

namespace sinew {

class CubeTopology final : public MeshTopology {
 public:
  Field<int> nx{this, "nx", 0, "number of points along x", "Grid"};
  Field<int> ny{this, "ny", 0, "number of points along y", "Grid"};
  Field<int> nz{this, "nz", 0, "number of points along z", "Grid"};
  Field<bool> internal_points{this, "internalPoints", false,
                              "also create the interior points (same numbering as RegularGridTopology)", "Grid"};
  Field<bool> split_normals{this, "splitNormals", false,
                            "duplicate edge and corner points so each face has flat normals", "Grid"};
  Field<Vec3> min{this, "min", Vec3::Zero(), "lower corner of the box", "Grid"};
  Field<Vec3> max{this, "max", Vec3::Ones(), "upper corner of the box", "Grid"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;

  enum class Plane { unknown, x0, x1, y0, y1, z0, z1 };
  // Index of lattice point (x,y,z); with splitNormals, the copy on face `p`.
  int point_index(int x, int y, int z, Plane p = Plane::unknown) const;

 protected:
  void generate() override;

 private:
  Vec3 lattice_point(int i) const;
  int count_ = 0;
  Vec3 p0_ = Vec3::Zero(), dx_ = Vec3::Zero(), dy_ = Vec3::Zero(), dz_ = Vec3::Zero();
};

}  // namespace sinew
