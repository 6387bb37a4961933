#include "sph/spatial_grid_container.h"

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

void SpatialGridContainer::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (!(cell_width.value() > 0))
    diag.error(where, describe() + ": cellWidth must be positive (got " + parse::format_double(cell_width.value()) + ")");
}

void SpatialGridContainer::init() {
  if (!mstate) mstate.set(node()->get_mechanical_state());
  if (!mstate || mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d mechanical state in its node");
    set_state(ComponentState::invalid);
    return;
  }
  grid_ = std::make_unique<sph::SpatialGrid>(cell_width.get());
}

void SpatialGridContainer::reinit() {
  if (!grid_ || grid_->cell_width() != cell_width.get()) grid_ = std::make_unique<sph::SpatialGrid>(cell_width.get());
}

void SpatialGridContainer::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid || !grid_) return;
  if (sort_points.value()) sort_now();
  else if (auto_update.value()) update(mstate->read(kPosition));
}

bool SpatialGridContainer::sort_now() {
  MechanicalState& s = *mstate;
  update(s.read(kPosition));
  grid_->reorder(new2old_);
  bool identity = new2old_.size() == s.size();
  for (std::size_t k = 0; identity && k < new2old_.size(); ++k) identity = new2old_[k] == k;
  if (identity || new2old_.size() != s.size()) return false;
  // SOFA renumbers through the PointSetTopologyModifier (POINTSRENUMBERING) or the
  // MechanicalObject's renumberValues: either way every vector of the state is permuted.
  // The grid's users (uniform masses, SPH force fields) keep no per-point data.
  std::vector<double> tmp;
  for (int id = kPosition; id <= kResetVelocity; ++id) {
    if (!s.has_vec(id)) continue;
    std::vector<double>& v = s.write(id);
    const std::size_t w = v.size() / s.size();
    tmp.assign(v.begin(), v.end());
    for (std::size_t k = 0; k < new2old_.size(); ++k)
      for (std::size_t c = 0; c < w; ++c) v[k * w + c] = tmp[new2old_[k] * w + c];
  }
  // The grid's own entries now name the old indices: rebuild.
  update(s.read(kPosition));
  return true;
}

void register_spatial_grid_container(Registry& r) {
  ComponentInfo info;
  info.name = "SpatialGridContainer";
  info.category = "SPH";
  info.description = "uniform hash grid finding close particle pairs (SofaSphFluid)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SpatialGridContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
