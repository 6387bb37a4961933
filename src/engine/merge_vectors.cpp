#include "engine/merge_vectors.h"

#include "core/registry.h"

namespace sinew {

template <class T>
MergeVectors<T>::MergeVectors() {
  add_input(&nb_inputs);
  inputs.grow(*this, nb_inputs.value(), [this](BaseField* f) { add_input(f); });
  add_output(&output);
}

template <class T>
void MergeVectors<T>::parse(AttributeMap& attrs, Diagnostics& diag) {
  inputs.grow(*this, read_field_count(*this, nb_inputs, attrs, diag, {inputs.prefix()}), [this](BaseField* f) { add_input(f); });
  Engine::parse(attrs, diag);
}

template <class T>
void MergeVectors<T>::init() {
  set_dirty();
  update();
}

template <class T>
void MergeVectors<T>::do_update() {
  std::size_t n = nb_inputs.get();
  if (n > inputs.size()) {
    msg_error("nbInputs = " + std::to_string(n) + " but only " + std::to_string(inputs.size()) +
              " inputs exist (their number is fixed when the scene is read): merging those");
    n = inputs.size();
  }
  T& out = output.edit();
  out.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const T& in = inputs[i].get();
    out.insert(out.end(), in.begin(), in.end());
  }
}

template class MergeVectors<std::vector<double>>;
template class MergeVectors<std::vector<int>>;
template class MergeVectors<std::vector<Vec2>>;
template class MergeVectors<std::vector<Vec3>>;

void register_merge_vectors(Registry& r) {
  ComponentInfo info;
  info.name = "MergeVectors";
  info.category = "Engine/Generate";
  info.description = "concatenates nbInputs vectors input1..N, in order";
  // SOFA names these templates after the Data's value type.
  info.templates = {"Data<double>", "Data<int>", "Data<Vec2d>", "Data<Vec3d>"};
  info.default_template = "Data<double>";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t == "Data<double>") return std::make_unique<MergeVectors<std::vector<double>>>();
    if (t == "Data<int>") return std::make_unique<MergeVectors<std::vector<int>>>();
    if (t == "Data<Vec2d>") return std::make_unique<MergeVectors<std::vector<Vec2>>>();
    if (t == "Data<Vec3d>") return std::make_unique<MergeVectors<std::vector<Vec3>>>();
    return nullptr;
  };
  r.add(std::move(info));
}

}  // namespace sinew
