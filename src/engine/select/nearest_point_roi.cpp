#include "engine/select/nearest_point_roi.h"

#include <cmath>
#include <numeric>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

NearestPointROI::NearestPointROI() {
  add_input(&input_indices1);
  add_input(&input_indices2);
  add_input(&radius);
  add_input(&use_rest_position);
  add_output(&indices1);
  add_output(&indices2);
  add_output(&edges);
  add_output(&index_pairs);
  add_output(&distances);
}

void NearestPointROI::init() {
  MechanicalState* local = node()->get_mechanical_state();
  if (!object1) object1.set(local);
  if (!object2) object2.set(local);
  if (!object1 || !object2) {
    msg_error("two mechanical states are needed (object1, object2, or the node's state)");
    set_state(ComponentState::invalid);
    return;
  }
  if (object1->state_type() != object2->state_type() || object1->info().coord_width != object1->info().deriv_width) {
    msg_error("object1 and object2 must be Vec states of the same template (got " +
              std::string(object1->info().name) + " and " + object2->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const char* which = use_rest_position.get() ? "rest_position" : "position";
  x1_ = object1->find_field(which);
  x2_ = object2->find_field(which);
  if (!x1_ || !x2_) {
    msg_error(std::string("a state has no '") + which + "'");
    set_state(ComponentState::invalid);
    return;
  }
  add_input(x1_);
  if (x2_ != x1_) add_input(x2_);
  // SOFA checks the radius only in reinit; at init a non-positive one is only worth a warning
  // (the squared radius is what the pairing compares).
  if (radius.get() <= 0) msg_warning("radius is not positive (" + std::to_string(radius.get()) + ")");
  set_dirty();  // computed when an output is read, as SOFA
}

void NearestPointROI::reinit() {
  if (radius.get() <= 0) {
    msg_error("radius must be positive (got " + std::to_string(radius.get()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (!x1_ || !x2_) return;
  set_state(ComponentState::valid);
  set_dirty();
  update();
}

void NearestPointROI::do_update() {
  if (state() == ComponentState::invalid || !x1_ || !x2_) return;
  const int kid = use_rest_position.get() ? kRestPosition : kPosition;
  x1_->update();
  x2_->update();
  const std::vector<double>& x1 = object1->read(kid);
  const std::vector<double>& x2 = object2->read(kid);
  if (x1.empty() || x2.empty()) return;  // SOFA leaves the outputs as they were
  const std::size_t w = static_cast<std::size_t>(object1->info().coord_width);
  const std::size_t n1 = x1.size() / w, n2 = x2.size() / w;

  std::vector<unsigned> f1 = input_indices1.get(), f2 = input_indices2.get();
  if (f1.empty()) {
    f1.resize(n1);
    std::iota(f1.begin(), f1.end(), 0u);
  }
  if (f2.empty()) {
    f2.resize(n2);
    std::iota(f2.begin(), f2.end(), 0u);
  }
  for (unsigned i : f1)
    if (i >= n1) {
      msg_error("inputIndices1 holds " + std::to_string(i) + ", beyond the " + std::to_string(n1) +
                " points of object1: no pairs");
      return;
    }
  for (unsigned i : f2)
    if (i >= n2) {
      msg_error("inputIndices2 holds " + std::to_string(i) + ", beyond the " + std::to_string(n2) +
                " points of object2: no pairs");
      return;
    }

  auto& o1 = indices1.edit();
  auto& o2 = indices2.edit();
  auto& oe = edges.edit();
  auto& op = index_pairs.edit();
  auto& od = distances.edit();
  o1.clear();
  o2.clear();
  oe.clear();
  op.clear();
  od.clear();
  const double r2 = radius.get() * radius.get();
  auto dist2 = [&](unsigned a, unsigned b) {
    double s = 0;
    for (std::size_t k = 0; k < w; ++k) {
      const double d = x2[b * w + k] - x1[a * w + k];
      s += d * d;
    }
    return s;
  };
  for (unsigned i2 : f2) {
    // std::min_element: the first of the nearest.
    unsigned best = f1.front();
    double bd = dist2(best, i2);
    for (std::size_t k = 1; k < f1.size(); ++k) {
      const double d = dist2(f1[k], i2);
      if (d < bd) {
        bd = d;
        best = f1[k];
      }
    }
    if (bd < r2) {
      o1.push_back(best);
      o2.push_back(i2);
      oe.push_back({i2 * 2, i2 * 2 + 1});
      op.insert(op.end(), {0u, best, 1u, i2});
      od.push_back(std::sqrt(bd));
    }
  }
}

void register_nearest_point_roi(Registry& r) {
  ComponentInfo info;
  info.name = "NearestPointROI";
  info.category = "Engine/Select";
  info.description = "pairs each point of a state with the nearest point of another within a radius";
  info.templates = {"Vec3d", "Vec2d", "Vec1d", "Vec6d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<NearestPointROI>(); };
  r.add(std::move(info));
}

}  // namespace sinew
