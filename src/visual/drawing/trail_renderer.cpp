#include "visual/drawing/trail_renderer.h"

#include "core/registry.h"
#include "visual/color_map.h"

namespace sinew {

namespace {

FlatVec empty_of(const std::string& tmpl) {
  FlatVec v;
  v.width = tmpl == "Rigid3d" ? 7 : 3;
  return v;
}

}  // namespace

TrailRenderer::TrailRenderer(const std::string& tmpl)
    : position(this, "position", empty_of(tmpl), "positions of the points followed", "Vector", "length") {
  listening.set(true);
}

void TrailRenderer::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (parse_color_map(color.value()).empty())
    diag.error(where, describe() + ": color " + color.value() + " is neither a colour scheme nor a list of colours");
}

void TrailRenderer::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_end) return;
  const FlatVec& x = position.get();
  const std::size_t n = x.size();
  if (n > trail_.size()) trail_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &x.data[i * x.width];
    trail_[i].emplace_back(p[0], p[1], p[2]);
    while (trail_[i].size() > nb_steps.get()) trail_[i].pop_front();
  }
}

void register_trail_renderer(Registry& r) {
  ComponentInfo info;
  info.name = "TrailRenderer";
  info.category = "Visual";
  info.description = "the paths of points over their last steps (viewer only)";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> { return std::make_unique<TrailRenderer>(t); };
  r.add(std::move(info));
}

}  // namespace sinew
