// TriangularBiquadraticSpringsForceField: membrane of biquadratic springs on
// the edges of a triangle mesh (SOFA's component of that name, Vec3d).
//
// With δ_e = |e|² − |e₀|² (+ dampingRatio·(dv·dp)/|e|²) per edge, it is the
// force of the energy
//   Σ_e ¼·s_e·δ_e²  +  Σ_triangles ½·Σ_j γ_j·δ_{j+1}·δ_{j+2}   (useAngularSprings)
//   + Σ_triangles (λ+μ)·3·A₀·(J − 1)⁴/4 for J = A/A₀ < 1      (compressible, with angular springs)
// where edge j of a triangle is the one opposite its vertex j, and per
// triangle (rest cotangents c_j, rest area A₀, from the rest positions):
//   s_j = (2c_j²(λ+μ) + μ)/(16A₀),  γ_j = (2c_{j+1}c_{j+2}(λ+μ) − μ)/(16A₀),
//   s_e = Σ s_j over the triangles holding the edge,
//   λ = Eν/(1−ν²), μ = E(1−ν)/(1−ν²).
// The compressible stiffness is SOFA's regularised tangent (a blend, by
// h = 1 − J, of the area-vector product and its trace), not the exact one.
// SOFA keeps edge and triangle data that follow topological changes: a removed
// triangle takes its s_j back from its edges, removed elements swap with the
// last, added edges get their rest length and added triangles add their s_j;
// so does this component (a handler on the topology). SOFA's getPotentialEnergy
// returns 0; potential_energy() here returns the energy above (damping left out).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

class TriangularBiquadraticSpringsForceField final : public ForceField {
 public:
  Field<std::vector<Vec3>> initial_points{this, "initialPoints", {}, "initial positions (default: the rest positions)",
                                          "Physics"};
  Field<double> poisson_ratio{this, "poissonRatio", 0.3, "Poisson ratio in Hooke's law", "Physics"};
  Field<double> young_modulus{this, "youngModulus", 1000.0, "Young modulus in Hooke's law", "Physics", "pressure (force/length²)"};
  Field<double> damping_ratio{this, "dampingRatio", 0.0, "ratio damping/stiffness", "Physics"};
  Field<bool> use_angular_springs{this, "useAngularSprings", true, "whether angular springs are used", "Physics"};
  Field<bool> compressible{this, "compressible", true,
                           "whether an additional energy penalises compression (with angular springs)", "Physics"};
  // Declared by SOFA and never read by its code.
  Field<double> matrix_regularization{this, "matrixRegularization", 0.4,
                                      "regularisation of the stiffness matrix, between 0 and 1 (unused, as in SOFA)",
                                      "Physics"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  std::optional<double> potential_energy() const override { return energy_; }

  double lambda() const { return lambda_; }
  double mu() const { return mu_; }

  struct EdgeInfo {
    double rest_square_length = 0, current_square_length = 0, delta_l2 = 0, stiffness = 0;
  };
  struct TriangleInfo {
    std::array<double, 3> gamma{}, stiffness{};
    std::array<Mat3, 3> dfdx{Mat3::Zero(), Mat3::Zero(), Mat3::Zero()};
    Vec3 current_normal = Vec3::Zero(), last_valid_normal = Vec3::Zero();
    double area = 0, rest_area = 0, J = 0;
    std::array<Vec3, 3> area_vector{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, dp{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    bool compressed = false;  // the compressible force acted at the last add_force
  };
  const std::vector<EdgeInfo>& edge_info() const { return edge_info_; }
  const std::vector<TriangleInfo>& triangle_info() const { return tri_info_; }

 private:
  bool rebuild();  // false: a degenerate triangle (error given)
  void create_edge(unsigned e, const MeshTopologyBase& t);
  bool create_triangle(unsigned i, const MeshTopologyBase& t);
  void update_matrix();
  bool lists_match() const;

  double lambda_ = 0, mu_ = 0;
  std::vector<EdgeInfo> edge_info_;
  std::vector<TriangleInfo> tri_info_;
  bool update_matrix_ = true;
  double energy_ = 0;
  std::vector<unsigned> flipped_;  // reused: triangles whose normal flipped in one add_force

  struct Follow final : TopologyHandler {
    TriangularBiquadraticSpringsForceField* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
