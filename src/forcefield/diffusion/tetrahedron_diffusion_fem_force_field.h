// TetrahedronDiffusionFEMForceField (Vec1d, Vec2d, Vec3d; SOFA's default Vec2d):
// linear diffusion of a scalar (or each component of a vector) field stored
// in the node's state, on a tetrahedral mesh whose geometry is another state:
// the Vec3d state tagged `tagMechanics`, searched in this node then upwards.
//
// Per tetrahedron (geometry positions p at init, V6 = (p1−p0)×(p2−p0)·(p0−p3),
// shape vectors s_j = ∓(p_{j+2}−p_{j+1})×(p_{j+3}−p_{j+1})/V6, − for even j,
// and coefficient D = tetraDiffusionCoefficient[t]·|V6|/6), each edge (k, l)
// gets c += s_k·s_l·D (isotropic), or s_k·(s_l + a((r−1)·a·s_l))·D with the
// tetrahedron's transverseAnisotropyArray direction a and anisotropyRatio r
// (SOFA does not normalise a). Then per edge (v0, v1):
//   f[v1] += (u[v1] − u[v0])·c,  f[v0] −= the same,
// df likewise with dx and kFactor (SOFA's mparams->kFactor(): this
// component's rayleighStiffness does not enter), assembled +c on (v0,v0),
// (v1,v1) and −c on (v0,v1), (v1,v0) for every component (SOFA assembles the
// first component only, for Vec2d and Vec3d: a deliberate difference). The
// coefficients are computed once at init (SOFA's reinit recomputes nothing).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class TetrahedronDiffusionFEMForceField : public ForceField {
 public:
  Field<double> constant_diffusion_coefficient{this, "constantDiffusionCoefficient", 1.0,
                                               "diffusion coefficient of every tetrahedron", "Diffusion"};
  Field<std::vector<double>> tetra_diffusion_coefficient{
      this, "tetraDiffusionCoefficient", {}, "diffusion coefficient per tetrahedron (default: the constant one)",
      "Diffusion"};
  Field<double> anisotropy_ratio{this, "anisotropyRatio", 1.0, "transverse anisotropy ratio (1: isotropic)",
                                 "Diffusion"};
  Field<std::vector<Vec3>> anisotropy_direction{this, "transverseAnisotropyArray", {},
                                                "anisotropy direction per tetrahedron", "Diffusion"};
  Field<std::string> tag_mechanics{this, "tagMechanics", "meca", "tag of the Vec3d state giving the geometry",
                                   "Diffusion"};
  Field<bool> draw_conduc{this, "drawConduc", false, "draw the conductivity map (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "tetrahedral topology (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  // Per edge of the topology: the coefficient c (SOFA's edgeDiffusionCoefficient).
  const std::vector<double>& edge_coefficients() const { return edge_coef_; }

 private:
  MechanicalState* find_geometry() const;
  void add_fluxes(const double* u, double* f, double factor) const;

  std::vector<double> edge_coef_;
  int width_ = 1;
};

}  // namespace sinew
