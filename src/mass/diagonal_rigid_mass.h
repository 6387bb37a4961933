// DiagonalMass on Rigid3d states (SOFA's DiagonalMass<Rigid3Types>): one rigid
// mass per frame, given in `vertexMass` as a list of SOFA's RigidMass<3> values,
// "mass volume [I00 I01 I02,I10 I11 I12,I20 I21 I22]" each (the brackets and
// commas optional). Unlike the Vec templates, nothing is computed from the
// topology: SOFA's Rigid3 initialisation reads vertexMass as given and ignores
// massDensity and totalMass. Per frame, M = diag(m, m, m, m·I): the inertia is
// scaled by the mass and used in world axes (not rotated with the frame), as
// SOFA's RigidDeriv × RigidMass product does.
#pragma once

#include "core/roles.h"

namespace sinew {

class DiagonalRigidMass final : public Mass {
 public:
  // Flattened: 11 numbers per frame (mass, volume, inertia by rows).
  Field<std::vector<double>> vertex_mass{this, "vertexMass", {}, "rigid mass of each frame: mass volume [inertia]",
                                         "Mass", "mass"};
  Field<double> mass_density{this, "massDensity", 1.0, "unused for rigid frames (as SOFA)", "Mass"};
  Field<double> total_mass{this, "totalMass", 1.0, "unused for rigid frames (as SOFA)", "Mass"};
  Field<bool> compute_mass_on_rest{this, "computeMassOnRest", true, "unused for rigid frames", "Mass"};
  Field<std::string> file_mass{this, "filename", "", "Xsp3.0 mass file (not supported)", "Mass"};
  Field<bool> show_gravity_center{this, "showGravityCenter", false, "draw the centre of gravity (viewer)",
                                  "Visualization"};
  Field<float> show_axis_size{this, "showAxisSizeFactor", 1.0f, "axis size (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the frames (default: the node's)"};
  Link<MechanicalState> geometry_state{this, "geometryState", "state holding the geometry (unused for rigid frames)"};

  DiagonalRigidMass();
  // vertexMass is read with SOFA's vector-of-RigidMass syntax (parse::read_rigid3_mass_list).
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  double total() const override;
  bool build_mass(MatrixSink& M) override;
  // SOFA's getPotentialEnergy: −Σ m_i·g·c_i over the frames' centres.
  std::optional<double> potential_energy() const override;

  struct Frame {
    double mass = 1;
    Mat3 inertia_mass = Mat3::Identity();      // inertia · mass
    Mat3 inv_inertia_mass = Mat3::Identity();  // its inverse
  };
  const std::vector<Frame>& frames() const { return frames_; }

 private:
  std::vector<Frame> frames_;  // one per DoF, from vertexMass
  // Points removed: the last frame's mass takes the slot (swap with last); points added get
  // SOFA's applyPointCreation value, a zero mass.
  struct Follow final : TopologyHandler {
    DiagonalRigidMass* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
};

}  // namespace sinew
