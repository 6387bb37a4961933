// SPHFluidSurfaceMapping (SofaSphFluid): the surface of a particle fluid as a
// triangle mesh, written into the output visual model (its positions and
// triangles) at every apply.
//
// The colour field φ(p) = Σ_i (1 − |p − x_i|²/R²)³ / ρ_i (R = `radius`, ρ_i
// the densities of the last SPHFluidForceField evaluation of the input's node,
// 1 without one) is sampled on the nodes of a lattice of spacing `step` that
// covers the particles (SOFA's sampling: same field, same nodes), and the
// surface φ = iso is extracted cell by cell. As SOFA, an isoValue left at its
// default 0.5 is divided by the field constant 315/(64πR³)·m of the SPH force
// field when there is one.
//
// Extraction: each lattice cube is split into six tetrahedra around its main
// diagonal (Kuhn) and each tetrahedron cut by the iso-surface (marching
// tetrahedra): no case table, a closed surface, vertices shared between
// neighbouring cells (one per cut lattice edge, found through per-node edge
// slots). SOFA uses the marching-cubes case table on the same cubes: the
// surface has the same level and the same vertices on the cube edges; the
// cube diagonals carry extra vertices here. Triangles face outward (towards
// lower φ).
#pragma once

#include <cstdint>
#include <vector>

#include "mapping/mapping_base.h"

namespace sinew {

class SPHFluidSurfaceMapping final : public MappingBase {
 public:
  SPHFluidSurfaceMapping() : MappingBase(StateType::vec3, StateType::vec3) {}

  Field<double> step{this, "step", 0.5, "spacing of the sampling lattice", "Surface", "length"};
  Field<double> radius{this, "radius", 2.0, "radius R of a particle's contribution to the colour field", "Surface",
                       "length"};
  Field<double> iso_value{this, "isoValue", 0.5, "level of the surface in the colour field", "Surface"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void apply(int x) override;
  void apply_j(int, int) override {}   // the surface carries no velocity
  void apply_jt(int, int) override {}  // nor forces (SOFA's applyJT does nothing)

  // The last surface (tests, viewers): positions (3 per vertex) and triangles.
  const std::vector<double>& surface_points() const { return points_; }
  const std::vector<std::uint32_t>& surface_triangles() const { return tris_; }
  double iso() const { return iso_; }

 protected:
  bool init_mapping() override;
  bool apply_at_init() const override { return true; }

 private:
  void sample_field(const std::vector<double>& x);
  void extract();
  std::uint32_t edge_vertex(std::size_t node_a, int dir, const int (&ca)[3], const int (&cb)[3], double va,
                            double vb);

  double iso_ = 0.5;
  bool warned_size_ = false;
  // Lattice: nodes (i, j, k) at origin_ + step·(i, j, k), i < nx_ ...
  double origin_[3] = {0, 0, 0};
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<double> field_;
  std::vector<std::int32_t> slot_;  // 7 per node: vertex on the edge leaving the node in that direction
  std::vector<double> points_;
  std::vector<std::uint32_t> tris_;
};

}  // namespace sinew
