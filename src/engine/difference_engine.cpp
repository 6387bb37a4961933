#include "engine/difference_engine.h"

#include "core/registry.h"

namespace sinew {

namespace {
FlatVec flat(int w) {
  FlatVec v;
  v.width = w;
  return v;
}
}  // namespace

DifferenceEngine::DifferenceEngine(int width)
    : input(this, "input", flat(width), "input vector", "Inputs"),
      substractor(this, "substractor", flat(width), "vector subtracted from input", "Inputs"),
      output(this, "output", flat(width), "input − substractor", "Outputs") {
  add_input(&input);
  add_input(&substractor);
  add_output(&output);
}

void DifferenceEngine::do_update() {
  const FlatVec& a = input.get();
  const FlatVec& b = substractor.get();
  if (a.size() != b.size() || a.width != b.width) {
    msg_warning("input (" + std::to_string(a.size()) + " values) and substractor (" + std::to_string(b.size()) +
                " values) differ in size: output not updated");
    return;
  }
  FlatVec& o = output.edit();
  o.width = a.width;
  o.data.resize(a.data.size());
  for (std::size_t i = 0; i < a.data.size(); ++i) o.data[i] = a.data[i] - b.data[i];
}

void register_difference_engine(Registry& r) {
  ComponentInfo info;
  info.name = "DifferenceEngine";
  info.category = "Engine/Transform";
  info.description = "difference of two vectors of values";
  info.templates = {"Vec1d", "Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t == "Vec1d") return std::make_unique<DifferenceEngine>(1);
    if (t == "Vec3d") return std::make_unique<DifferenceEngine>(3);
    return nullptr;
  };
  r.add(std::move(info));
}

}  // namespace sinew
