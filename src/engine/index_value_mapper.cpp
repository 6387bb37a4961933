#include "engine/index_value_mapper.h"

#include "core/alloc_check.h"
#include "core/registry.h"

namespace sinew {

IndexValueMapper::IndexValueMapper() {
  add_input(&input_values);
  add_input(&indices);
  add_input(&value);
  add_output(&output_values);
}

void IndexValueMapper::init() {
  set_dirty();
  update();
}

void IndexValueMapper::do_update() {
  const std::vector<unsigned>& ids = indices.get();
  const double v = value.get(), d = default_value.get();
  std::vector<double>& out = output_values.edit();
  out = input_values.get();
  for (unsigned id : ids) {
    if (id >= out.size()) {
      if (!check_allocation(*this, "indices", std::to_string(id), static_cast<double>(id) + 1, sizeof(double))) {
        out = input_values.get();
        return;
      }
      out.resize(static_cast<std::size_t>(id) + 1, d);
    }
    out[id] = v;
  }
}

void register_index_value_mapper(Registry& r) {
  ComponentInfo info;
  info.name = "IndexValueMapper";
  info.category = "Engine/Transform";
  info.description = "values per index: input values, `value` at the given indices, `defaultValue` in the gaps";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<IndexValueMapper>(); };
  r.add(std::move(info));
}

}  // namespace sinew
