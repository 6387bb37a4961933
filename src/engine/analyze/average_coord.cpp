#include "engine/analyze/average_coord.h"

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

AverageCoord::AverageCoord(StateType type)
    : average(this, "average", empty_coords(type), "mean of the selected coordinates", "Outputs"), type_(type) {
  add_input(&indices);
  add_input(&vec_id);
  add_output(&average);
}

void AverageCoord::init() {
  if (!mstate) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state: set 'mstate' or put a MechanicalObject in the node");
    set_state(ComponentState::invalid);
    return;
  }
  if (mstate->state_type() != type_) {
    msg_error(std::string("the state is ") + mstate->info().name + ", the template " + state_type_info(type_).name);
    set_state(ComponentState::invalid);
    return;
  }
  set_dirty();
}

void AverageCoord::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  set_dirty();
  update();
}

void AverageCoord::do_update() {
  if (!mstate || state() == ComponentState::invalid) return;
  int id = -1;
  switch (vec_id.get()) {
    case 1: id = kPosition; break;
    case 2: id = kRestPosition; break;
    case 3: id = kFreePosition; break;
    case 4: id = kResetPosition; break;
    default: break;
  }
  if (id < 0) {
    msg_error("vecId " + std::to_string(vec_id.get()) +
              " is not a coordinate vector (1 position, 2 rest_position, 3 free_position, 4 reset_position)");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& x = mstate->read(id);
  const std::size_t w = static_cast<std::size_t>(state_type_info(type_).coord_width);
  const std::size_t npts = x.size() / w;
  const std::vector<unsigned>& ids = indices.get();
  const std::size_t n = ids.empty() ? npts : ids.size();
  if (n == 0) {
    msg_error("nothing to average (no coordinates)");
    set_state(ComponentState::invalid);
    return;
  }
  std::vector<double> c(w, 0.0);
  if (type_ == StateType::rigid3) c[6] = 1.0;  // SOFA's default Coord: identity orientation
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = ids.empty() ? i : ids[i];
    if (k >= npts) {
      msg_error("indices[" + std::to_string(i) + "] = " + std::to_string(k) + " is beyond the " +
                std::to_string(npts) + " coordinates");
      set_state(ComponentState::invalid);
      return;
    }
    for (std::size_t j = 0; j < w; ++j) c[j] += x[k * w + j];
  }
  const double s = 1.0 / static_cast<double>(n);
  for (double& v : c) v *= s;
  FlatVec out;
  out.width = static_cast<int>(w);
  out.data = std::move(c);
  average.set(std::move(out));
}

void register_average_coord(Registry& r) {
  ComponentInfo info;
  info.name = "AverageCoord";
  info.category = "Engine/Analyze";
  info.description = "mean of some coordinates of a mechanical state";
  info.templates = {"Vec2d", "Vec3d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<AverageCoord>();
  r.add(std::move(info));
}

}  // namespace sinew
