// PartialFixedProjectiveConstraint: fixes chosen directions (components) of
// listed DoFs (spec/mechanics.md §4). fixedDirections has one flag per
// derivative component, all true by default.
#include <algorithm>

#include "core/registry.h"
#include "core/roles.h"
#include "projective/indices_in_state.h"

namespace sinew {

namespace {

class PartialFixedProjectiveConstraint final : public ProjectiveConstraint {
 public:
  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the constrained DoFs (default: 0)",
                                       "Constraint"};
  Field<bool> fix_all{this, "fixAll", false, "constrain every DoF", "Constraint"};
  Field<std::vector<int>> fixed_directions{this, "fixedDirections", {},
                                           "1 per derivative component to fix (default: all)", "Constraint"};
  Field<bool> project_velocity_flag{this, "projectVelocity", false,
                                    "also zero the fixed velocity components after each step", "Constraint"};
  Field<bool> activate_project_velocity{this, "activate_projectVelocity", false, "same as projectVelocity",
                                        "Constraint"};
  Field<bool> show_object{this, "showObject", true, "draw (viewer)", "Visualization"};
  Field<double> draw_size{this, "drawSize", 0.0, "point size (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override {
    ProjectiveConstraint::init();
    if (state() != ComponentState::valid) return;
    const int w = mstate->info().deriv_width;
    mask_.assign(w, true);
    const auto& fd = fixed_directions.get();
    for (int c = 0; c < w && c < static_cast<int>(fd.size()); ++c) mask_[c] = fd[c] != 0;
    keep_indices_in_state(*this, indices.get(), mstate->size(), active_);
  }
  void project_response(int dx) override { zero(dx); }
  // SOFA zeroes the fixed directions of the listed DOFs in every row.
  void project_jacobian(ConstraintMatrix& J) override {
    auto clear = [&](int i) {
      for (int c = 0; c < static_cast<int>(mask_.size()); ++c)
        if (mask_[c]) J.zero_dof(i, c, 1);
    };
    if (fix_all.value())
      for (std::size_t i = 0; i < mstate->size(); ++i) clear(static_cast<int>(i));
    else
      for (unsigned i : active_) clear(static_cast<int>(i));
  }
  void project_velocity(int v, double) override {
    if (project_velocity_flag.value() || activate_project_velocity.value()) zero(v);
  }
  void project_position(int, double) override {}
  bool dirichlet_indices(std::vector<std::size_t>& out) override {
    const std::size_t w = mask_.size();
    auto push = [&](std::size_t i) {
      for (std::size_t c = 0; c < w; ++c)
        if (mask_[c]) out.push_back(i * w + c);
    };
    if (fix_all.value())
      for (std::size_t i = 0; i < mstate->size(); ++i) push(i);
    else
      for (unsigned i : active_) push(i);
    return true;
  }

 private:
  void zero(int id) {
    std::vector<double>& d = mstate->write(id);
    const std::size_t w = mask_.size();
    auto clear = [&](std::size_t i) {
      for (std::size_t c = 0; c < w; ++c)
        if (mask_[c]) d[i * w + c] = 0.0;
    };
    if (fix_all.value())
      for (std::size_t i = 0; i < mstate->size(); ++i) clear(i);
    else
      for (unsigned i : active_) clear(i);
  }
  std::vector<bool> mask_;
  std::vector<unsigned> active_;
};

}  // namespace

void register_partial_fixed_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "PartialFixedProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "fixes chosen directions of a set of degrees of freedom";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<PartialFixedProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
