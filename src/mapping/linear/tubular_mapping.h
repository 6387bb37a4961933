// TubularMapping: a ring of points around each Rigid3d frame, the moving skin
// of a beam (SOFA's TubularMapping, Sofa/Component/Mapping/Linear).
// Rigid3d → Vec3d; pairs with Edge2QuadTopologicalMapping, which numbers the
// same points (ring j of frame i is output point i·N + j) and builds the quads.
//
// apply: with R the rotation of frame i (centre c), θj = 2πj/N and ρi the
// radius of ring i,
//   r_ij = (R·y·cos θj + R·z·sin θj)·ρi,   out_ij = c + r_ij;
// J: v_ij = v_i + ω_i × r_ij; Jᵀ: F_i += Σj f_ij, τ_i += Σj r_ij × f_ij.
// r_ij is kept from the last apply, as in SOFA (so J is exact at the positions
// last mapped; there is no geometric stiffness: SOFA treats it as linear).
//
// `peak` narrows the first (peak > 0) or last (peak < 0) |peak| rings to a
// point: ρi = ρ·i/peak for i < peak, ρ·(n−1−i)/|peak| for the last ones.
//
// One deliberate difference from SOFA: SOFA's applyJT on forces never resets
// its running sums between frames, so frame i receives the forces of rings
// 0…i (not the transpose of its applyJ). Sinew gives each frame its own ring's
// forces, the adjoint of J. SOFA's examples put no force on the tube points
// (visual skins), so their numbers are the same either way.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class TubularMapping final : public MappingBase {
 public:
  TubularMapping() : MappingBase(StateType::rigid3, StateType::vec3) {}

  Field<unsigned> nb_points_on_each_circle{this, "nbPointsOnEachCircle", 0u,
                                           "number of points on each ring (discretisation of the circles)", "Mapping"};
  Field<double> radius{this, "radius", 0.0, "radius of the rings (required)", "Mapping", "length"};
  Field<int> peak{this, "peak", 0,
                  "0: no peak; k > 0: the first k rings narrow to a point; k < 0: the last |k| rings", "Mapping"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  // An entry v on ring point k gives (v, r_k × v) on its frame k / N.
  bool has_jt_entry() const override { return out_ != nullptr; }
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;

 private:
  unsigned n_ = 0;                  // points per ring
  std::vector<double> cos_, sin_;   // cos θj, sin θj
  std::vector<double> rotated_;     // r_ij at the last apply, 3 per output point
};

}  // namespace sinew
