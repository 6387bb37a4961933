#include "engine/points_from_indices.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
FlatVec flat3() {
  FlatVec v;
  v.width = 3;
  return v;
}
}  // namespace

PointsFromIndices::PointsFromIndices()
    : position(this, "position", flat3(),
               "coordinates of the points (default: the positions of the mechanical state of the context)",
               "Inputs"),
      indices_position(this, "indices_position", flat3(), "coordinates of the points whose indices are given",
                       "Outputs") {
  add_input(&position);
  add_input(&indices);
  add_output(&indices_position);
}

void PointsFromIndices::init() {
  if (position.get().data.empty() && !position.parent()) {
    Node& n = *node();
    MechanicalState* ms = n.find_local<MechanicalState>();
    if (!ms) ms = n.find_up<MechanicalState>();
    if (ms)
      if (BaseField* p = ms->find_field("position")) position.set_parent(p);
  }
  set_dirty();
  update();
}

void PointsFromIndices::do_update() {
  const FlatVec& x = position.get();
  if (x.data.empty()) return;  // SOFA leaves the output as it was
  const std::vector<unsigned>& ids = indices.get();
  FlatVec& out = indices_position.edit();
  out.width = x.width;
  out.data.clear();
  const std::size_t n = x.size(), w = static_cast<std::size_t>(x.width);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] >= n) {
      msg_error("index " + std::to_string(i) + " of 'indices' is " + std::to_string(ids[i]) + ", beyond the " +
                std::to_string(n) + " points of 'position': ignored");
      continue;
    }
    const double* c = &x.data[ids[i] * w];
    // SOFA's Vec equality: every coordinate within 1e-6.
    auto same = [&](const double* o) {
      for (std::size_t k = 0; k < w; ++k)
        if (!(std::abs(c[k] - o[k]) < 1e-6)) return false;
      return true;
    };
    bool seen = false;
    for (std::size_t k = 0; k < out.data.size() && !seen; k += w) seen = same(&out.data[k]);
    if (!seen) out.data.insert(out.data.end(), c, c + w);
  }
}

void register_points_from_indices(Registry& r) {
  ComponentInfo info;
  info.name = "PointsFromIndices";
  info.category = "Engine/Select";
  info.description = "the coordinates of the points whose indices are given (each distinct point once)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<PointsFromIndices>(); };
  r.add(std::move(info));
}

}  // namespace sinew
