// UniformMass: the same mass on every DoF (spec/mechanics.md §1.1).
//
// Vec templates: M = m·I. Rigid3d: vertexMass is "mass volume I00 … I22",
// the matrix optionally written "[I00 I01 I02,I10 I11 I12,I20 I21 I22]";
// the inertia tensor is scaled by the mass and expressed in world axes
// (never rotated with the body, as SOFA does). Rigid2d: "mass volume inertia",
// a scalar inertia. Gravity is added in addForce
// unless separateGravity.
#pragma once

#include "core/roles.h"

namespace sinew {

class UniformMass final : public Mass {
 public:
  Field<std::vector<double>> vertex_mass{
      this, "vertexMass", {1.0}, "mass of each DoF; Rigid3d: mass volume I00 I01 … I22", "Mass", "mass"};
  Field<double> total_mass{this, "totalMass", 1.0, "mass of the whole object; wins over vertexMass", "Mass", "mass"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "DoFs having a mass (default: all)", "Mass"};
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1), "restrict to DoFs [first, last]", "Mass"};
  Field<bool> preserve_total_mass{this, "preserveTotalMass", false, "keep totalMass when DoFs change", "Mass"};
  Field<std::string> filename{this, "filename", "", "Rigid3d mass file (.rigid)", "Mass"};
  Field<bool> show_gravity_center{this, "showGravityCenter", false, "draw the centre of gravity (viewer)",
                                  "Visualization"};
  Field<double> show_axis_size{this, "showAxisSizeFactor", 1.0, "axis size (viewer)", "Visualization"};
  Field<bool> compute_mapping_inertia{this, "compute_mapping_inertia", false, "unused", "Mass"};
  Field<bool> show_initial_center{this, "showInitialCenterOfGravity", false, "viewer", "Visualization"};
  Field<bool> show_x0{this, "showX0", false, "viewer", "Visualization"};

  UniformMass() { filename.set_file(true); }

  // Rigid3d: vertexMass is read with SOFA's Rigid3Mass syntax, "mass volume [I00 I01 I02,I10 …]"
  // (parse::read_rigid3_mass); the other templates read it as a list of numbers.
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  double total() const override { return total_mass.value(); }
  bool build_mass(MatrixSink& M) override;
  // SOFA's getPotentialEnergy: −Σ m·g·x over the DoFs with mass (their centres for Rigid3d).
  std::optional<double> potential_energy() const override;

  double mass() const { return m_; }
  // Rigid3d: (inertia · mass)⁻¹ of each DoF, world axes (SOFA's invInertiaMassMatrix).
  const Mat3& inv_inertia_mass() const { return inv_inertia_mass_; }

 private:
  double m_ = 1.0;                    // mass of each DoF
  // Reads a .rigid file (SOFA's loadRigidMass): mass and inertia of each DoF; false after an error.
  bool load_rigid_file(double& mass, Mat3& inertia);

  Mat3 inertia_mass_ = Mat3::Identity();   // Rigid3d: inertia·mass (world axes)
  Mat3 inv_inertia_mass_ = Mat3::Identity();
  double inertia_mass2_ = 1.0;             // Rigid2d: inertia·mass
  Mat3 inertia_ = Mat3::Identity();        // per unit mass (resizes with preserveTotalMass)
  double inertia2_ = 1.0;
  std::vector<unsigned> active_;      // DoFs with mass
  // The topology's point changes (SOFA's indices TopologySubsetData): a removed point leaves the
  // list (its entry takes the list's last), the last point's index becomes the slot's; new points
  // join; each ending event resizes the mass (totalMass = n·m, or m = totalMass/n when
  // preserveTotalMass).
  struct Follow final : TopologyHandler {
    UniformMass* owner = nullptr;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow_;
  void update_mass_on_resize(std::size_t n);
};

}  // namespace sinew
