// MechanicalObject: the degrees of freedom of a body (positions, velocities,
// forces and solver temporaries), stored as flat arrays.
//
// One class for every template: the element layout (Vec3d: 3 scalars,
// Rigid3d: 7 for positions and 6 for derivatives) is chosen at creation.
// Initial positions come from `position`, a `src=` loader, or the node's
// first mesh topology (spec/framework.md §5).
#pragma once

#include <map>

#include "core/constraint_matrix_field.h"
#include "core/roles.h"

namespace sinew {

class MechanicalObject final : public MechanicalState {
 public:
  explicit MechanicalObject(StateType type);

  Field<FlatVec> position, velocity, force, external_force, rest_position, deriv_x, free_position, free_velocity,
      reset_position, reset_velocity;
  // Outputs of the constraint solvers (SOFA's d_c and the "lambda" vector a
  // GenericConstraintSolver allocates on every state): the Jacobian rows on this
  // state, and Jᵀλ, the constraint force of the last solve on each DoF.
  ConstraintMatrixField constraint{this, this};
  Field<FlatVec> lambda;
  Field<FlatVec>* lambda_field() override { return &lambda; }
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied at init", "Transformation", "length"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation applied at init (Euler angles, degrees)",
                       "Transformation", "degrees"};
  Field<Vec3> scale3d{this, "scale3d", Vec3::Ones(), "scale applied at init", "Transformation"};
  Field<Vec3> translation2{this, "translation2", Vec3::Zero(), "translation applied after rest_position is stored",
                           "Transformation", "length"};
  Field<Vec3> rotation2{this, "rotation2", Vec3::Zero(), "rotation applied after rest_position is stored (degrees)",
                        "Transformation", "degrees"};
  Field<double> rest_scale{this, "restScale", 1.0, "rest_position = restScale · position when derived", "Transformation"};
  Field<bool> use_topology{this, "useTopology", true, "take initial positions from the node's mesh topology",
                           "Topology"};
  Field<int> size_field{this, "size", 1, "number of degrees of freedom", "Infos"};
  Field<int> reserve{this, "reserve", 0, "capacity hint", "Infos"};
  // Viewer-only fields (render/draw_list.h, render/draw_text.h draw some).
  Field<bool> show_object{this, "showObject", false, "draw the points (viewer)", "Visualization"};
  Field<double> show_object_scale{this, "showObjectScale", 0.1, "point size (viewer)", "Visualization"};
  Field<bool> show_indices{this, "showIndices", false, "draw each point's index (viewer)", "Visualization"};
  // SOFA's current meaning: a factor on a constant screen height (30 px at 1), no longer a world size.
  Field<double> show_indices_scale{this, "showIndicesScale", 1.0, "size of the indices (1: 30 pixels high)",
                                   "Visualization"};
  Field<bool> show_vectors{this, "showVectors", false, "draw velocities (viewer)", "Visualization"};
  Field<double> show_vectors_scale{this, "showVectorsScale", 0.0001, "vector scale (viewer)", "Visualization"};
  Field<int> draw_mode{this, "drawMode", 0, "0: points, 1: spheres, ... (viewer)", "Visualization"};
  Field<std::vector<double>> show_color{this, "showColor", {1, 1, 1, 1}, "colour (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the initial positions"};

  // MechanicalState
  StateType state_type() const override { return type_; }
  std::size_t size() const override { return size_; }
  void resize(std::size_t n) override;
  void remove_points(const std::vector<unsigned>& decreasing) override;
  void add_points(std::size_t n, const std::vector<std::vector<unsigned>>& ancestors,
                  const std::vector<std::vector<double>>& coefficients) override;
  const std::vector<double>& read(int id) const override;
  bool has_vec(int id) const override;
  std::vector<double>& write(int id) override;
  void touch(int id) override;
  void add_deriv_to_coord(int x_out, int x_in, int v, double h) override;
  void end_integration() override;

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override;
  void store_reset_state() override;
  void reset() override;

 private:
  Field<FlatVec>* standard(int id);
  std::vector<double>& storage(int id);  // sized to the state, no version change
  void resize_vec(std::vector<double>& v, bool coord, std::size_t n) const;
  void apply_transform(std::vector<double>& x, const Vec3& scale, const Vec3& rot_deg, const Vec3& trans) const;

  StateType type_;
  std::size_t size_ = 1;
  std::map<int, std::vector<double>> dynamic_;
};

}  // namespace sinew
