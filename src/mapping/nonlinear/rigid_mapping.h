// RigidMapping: points attached to rigid frames (spec/mechanics.md §6.3).
// Rigid3d → Vec3d, Rigid3d → Rigid3d (frames attached to frames) and
// Rigid2d → Vec2d.
//
// Local coordinates (`initialPoints`) are taken at init from the output's
// current positions when not given: as they are, or converted to the frame of
// their rigid with globalToLocalCoords. The rigid of point i is
// rigidIndexPerPoint[i] when that list has one entry per point, else `index`
// (counted from the end with indexFromEnd).
// apply: rp_i = R(q_r)·local_i, out_i = c_r + rp_i; J: v_i = v_r + ω_r × rp_i;
// Jᵀ: F_r += f_i, τ_r += rp_i × f_i. Geometric stiffness (Rigid3d inputs):
// per frame K_r = Σ_i [f_i]×·[rp_i]× on its rotation, so that τ_r += k·K_r·δω_r
// (Exact: as is, matrix-free only since it is not symmetric; Stabilized:
// symmetrised, then its positive eigenvalues set to zero, SOFA's NSD
// projection, and also available as assembled entries).
// Rigid3d outputs also carry an orientation: out_i = (c_r + rp_i, q_r·q_i),
// ω_i = ω_r, and their torques add to the rigid's (τ_r += τ_i + rp_i × f_i).
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class RigidMapping final : public MappingBase {
 public:
  RigidMapping(StateType in, StateType out) : MappingBase(in, out) { filename.add_alias("fileRigidMapping"); }

  Field<std::vector<double>> initial_points{
      this, "initialPoints", {}, "mapped points in the frame of their rigid", "Mapping"};
  Field<unsigned> index{this, "index", 0u, "index of the input rigid", "Mapping"};
  Field<std::string> filename{this, "filename", "", "Xsp file to read the mapped points from", "Mapping"};
  Field<bool> use_x0{this, "useX0", false,
                     "read the local points from the output rest positions (follows topology changes)", "Mapping"};
  Field<bool> index_from_end{this, "indexFromEnd", false, "count 'index' from the last input rigid", "Mapping"};
  Field<std::vector<unsigned>> rigid_index_per_point{
      this, "rigidIndexPerPoint", {}, "rigid index of each mapped point", "Mapping"};
  Field<bool> global_to_local_coords{this, "globalToLocalCoords", false,
                                     "initial output positions are world coordinates", "Mapping"};
  Field<std::string> geometric_stiffness{this, "geometricStiffness", "None",
                                         "geometric stiffness: None, Exact or Stabilized (0, 1, 2)", "Mapping"};

  // Contact points on rigid collision models (SOFA's RigidContactMapper): the
  // collision response binds the mapping to the model's Rigid3d state and a
  // Vec3d state of its own, then empties it and adds points (given in the frame
  // of their rigid) between steps. Precondition: Rigid3d → Vec3d.
  void bind_contact_states(MechanicalState& in, MechanicalState& out);
  void clear_points();
  unsigned add_point(const Vec3& local, unsigned rigid);

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  // Rigid3d → Vec3d: an entry v on point i gives (v, p_i × v) on its frame.
  bool has_jt_entry() const override;
  void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const override;
  void apply_djt(int df, int dx, double k) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  // The Exact geometric stiffness is not symmetric: not available as assembled entries.
  bool build_geometric_stiffness(MatrixSink& K) override;

 protected:
  bool init_mapping() override;

 private:
  bool rigid3() const { return in_type() == StateType::rigid3; }
  // Stabilized: the 3×3 rotation block of each frame into blocks_ (9 per frame, row-major;
  // has_children_ says which frames have points), from the output's forces.
  void stabilized_blocks();
  std::vector<double> blocks_;
  std::vector<char> has_children_;
  std::vector<unsigned> rigid_;    // rigid index per point
  std::vector<double> local_;      // local coordinates, dim_ per point
  std::vector<double> rotated_;    // R·(local centre) at the last apply, spatial dimension per point
  int dim_ = 3;                    // output coordinate width (Rigid3d: 7)
  int pd_ = 3;                     // spatial dimension of the output points
  int dw_ = 3;                     // output derivative width (Rigid3d: 6)
  bool rigid_out_ = false;
  int gs_ = 0;
};

}  // namespace sinew
