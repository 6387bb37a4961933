#include "engine/values_from_indices.h"

#include "core/registry.h"

namespace sinew {

namespace {
FlatVec flat(int w) {
  FlatVec v;
  v.width = w;
  return v;
}
}  // namespace

ValuesFromIndices::ValuesFromIndices(int width)
    : in(this, "in", flat(width), "input values", "Inputs"),
      out(this, "out", flat(width), "the values at the given indices", "Outputs") {
  in.add_alias("input");
  out.add_alias("output");
  add_input(&in);
  add_input(&indices);
  add_output(&out);
  add_output(&out_str);
}

void ValuesFromIndices::init() {
  set_dirty();
  update();
}

void ValuesFromIndices::do_update() {
  const FlatVec& v = in.get();
  const std::vector<unsigned>& ids = indices.get();
  FlatVec& o = out.edit();
  o.width = v.width;
  o.data.clear();
  o.data.reserve(ids.size() * static_cast<std::size_t>(v.width));
  const std::size_t n = v.size(), w = static_cast<std::size_t>(v.width);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] >= n) {
      msg_error("invalid input index " + std::to_string(i) + ": " + std::to_string(ids[i]) + " >= " +
                std::to_string(n) + " values in 'in'");
      continue;
    }
    const double* c = &v.data[ids[i] * w];
    o.data.insert(o.data.end(), c, c + w);
  }
  out_str.set(out.text());
}

void register_values_from_indices(Registry& r) {
  ComponentInfo info;
  info.name = "ValuesFromIndices";
  info.category = "Engine/Select";
  info.description = "the values of a vector at the given indices";
  // SOFA's value types; SOFA also has a string variant, unused by its scenes.
  static const std::vector<std::pair<std::string, int>> kWidths = {
      {"int", 1},          {"unsigned int", 1}, {"fixed_array<unsigned int,2>", 2},
      {"fixed_array<unsigned int,3>", 3},       {"fixed_array<unsigned int,4>", 4},
      {"fixed_array<unsigned int,8>", 8},       {"double", 1},
      {"Vec2d", 2},        {"Vec3d", 3},        {"Vec4d", 4},
      {"Vec6d", 6},        {"Rigid2d", 3},      {"Rigid3d", 7}};
  for (const auto& [t, w] : kWidths) info.templates.push_back(t);
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    for (const auto& [name, w] : kWidths)
      if (name == t) return std::make_unique<ValuesFromIndices>(w);
    return nullptr;
  };
  r.add(std::move(info));
}

}  // namespace sinew
