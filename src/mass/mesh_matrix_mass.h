// MeshMatrixMass: consistent (or lumped) mass from the element measures of
// the topology, stored as a per-vertex diagonal and a per-edge off-diagonal
// (spec/mechanics.md §1.3). Non-lumped by default; gravity uses the lumped
// row sums; computed on current positions unless computeMassOnRest.
#pragma once

#include "core/roles.h"

namespace sinew {

class MeshMatrixMass final : public Mass {
 public:
  Field<std::vector<double>> mass_density{
      this, "massDensity", {}, "mass density: one value, or one per element", "Mass", "mass/length³"};
  Field<double> total_mass{this, "totalMass", 1.0, "total mass of the object; wins over the others", "Mass", "mass"};
  Field<std::vector<double>> vertex_mass{this, "vertexMass", {}, "diagonal mass of each vertex (internal)", "Mass", "mass"};
  Field<std::vector<double>> edge_mass{this, "edgeMass", {}, "off-diagonal mass of each edge (internal)", "Mass"};
  Field<bool> compute_mass_on_rest{this, "computeMassOnRest", false,
                                   "compute the element measures on the rest positions (else current positions)",
                                   "Mass"};
  Field<bool> lumping{this, "lumping", false, "lump the mass matrix on its diagonal", "Mass"};
  Field<bool> print_mass{this, "printMass", false, "print the total mass (debug)", "Mass"};
  Field<bool> show_gravity_center{this, "showGravityCenter", false, "draw the centre of gravity (viewer)",
                                  "Visualization"};
  Field<double> show_axis_size{this, "showAxisSizeFactor", 1.0, "axis size (viewer, rigids)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the elements (default: the node's)"};
  Link<MechanicalState> geometry_state{this, "geometryState",
                                       "state holding the geometry (default: the topology's node state)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  double total() const override { return total_mass.value(); }
  bool build_mass(MatrixSink& M) override;
  bool is_diagonal() const override { return lumping.value(); }

  double lumping_coefficient() const { return coef_; }

 private:
  // Fills vertexMass/edgeMass with the element shares for per-element
  // densities `rho` and returns the accumulated total (SOFA's order).
  double compute_mass(const std::vector<double>& rho);
  bool lumped_ = false;
  double coef_ = 0;                            // SOFA m_massLumpingCoeff
  int kind_ = 0;                               // meshgeo::MassElement
  std::vector<Edge> edges_;                    // topology edges, in order
  std::vector<std::array<unsigned, 12>> elem_edges_;  // edge indices of each element
  std::size_t n_elements_ = 0;
};

}  // namespace sinew
