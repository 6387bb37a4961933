// DiagonalMass: lumped mass per vertex from the element measures of the
// topology (spec/mechanics.md §1.2): edge L/2, triangle A/3, quad A/4,
// tetra V/4, hexa V/8 (6-tetrahedron volume), times the density.
// Initialisation priority: totalMass > massDensity > vertexMass.
#pragma once

#include "core/roles.h"

namespace sinew {

class DiagonalMass final : public Mass {
 public:
  Field<std::vector<double>> vertex_mass{this, "vertexMass", {}, "mass of each vertex", "Mass", "mass"};
  Field<double> mass_density{this, "massDensity", 1.0, "mass density (kg per unit length, area or volume)", "Mass", "mass/length³"};
  Field<double> total_mass{this, "totalMass", 1.0, "total mass of the object; wins over the others", "Mass", "mass"};
  Field<bool> compute_mass_on_rest{this, "computeMassOnRest", true,
                                   "compute the element measures on the rest positions (else current positions)",
                                   "Mass"};
  Field<std::string> file_mass{this, "filename", "", "Xsp3.0 mass file (not supported)", "Mass"};
  Field<bool> show_gravity_center{this, "showGravityCenter", false, "draw the centre of gravity (viewer)",
                                  "Visualization"};
  Field<float> show_axis_size{this, "showAxisSizeFactor", 1.0f, "axis size (viewer, rigids)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the elements (default: the node's)"};
  Link<MechanicalState> geometry_state{this, "geometryState",
                                       "state holding the geometry (default: the topology's node state)"};

  DiagonalMass();
  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  double total() const override { return total_mass.value(); }
  bool build_mass(MatrixSink& M) override;
  // SOFA's getPotentialEnergy: −Σ m_i·g·x_i.
  std::optional<double> potential_energy() const override;

  const std::vector<double>& masses() const { return vertex_mass.value(); }

 private:
  // Σ of the per-vertex shares with density `rho`, written into vertexMass.
  double compute_vertex_mass(double rho);
  // Topological changes (SOFA's vertexMass handler): a removed element takes its share
  // (massDensity · rest measure / vertex count) from its vertices and from totalMass; a
  // removed point's mass is replaced by the last point's (swap with last).
  void on_topology_change(const MeshTopologyBase& t, const TopologyChange& c);
  struct Follow final : TopologyHandler {
    DiagonalMass* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override { owner->on_topology_change(t, c); }
  } follow_;
  int kind_ = 0;  // meshgeo::MassElement
};

}  // namespace sinew
