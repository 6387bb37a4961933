#include "engine/norm_engine.h"

#include <cmath>

#include "core/registry.h"

namespace sinew {

NormEngine::NormEngine() : input(this, "input", FlatVec{3, {}}, "input 3d vectors", "Inputs") {
  add_input(&input);
  add_output(&output);
  add_input(&norm_type);
}

namespace {
double l_norm(const double* v, int w, int l) {
  double n = 0;
  if (l == 2) {
    for (int c = 0; c < w; ++c) n += v[c] * v[c];
    return std::sqrt(n);
  }
  if (l < 0) {
    for (int c = 0; c < w; ++c) n = std::max(n, std::fabs(v[c]));
    return n;
  }
  if (l == 1) {
    for (int c = 0; c < w; ++c) n += std::fabs(v[c]);
    return n;
  }
  if (l == 0) {
    for (int c = 0; c < w; ++c)
      if (v[c] != 0.0) n += 1;
    return n;
  }
  for (int c = 0; c < w; ++c) n += std::pow(std::fabs(v[c]), l);
  return std::pow(n, 1.0 / l);
}
}  // namespace

void NormEngine::do_update() {
  const FlatVec& in = input.get();
  const int l = norm_type.get();
  std::vector<double>& out = output.edit();
  const std::size_t n = in.size();
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = l_norm(&in.data[i * in.width], in.width, l);
}

void register_norm_engine(Registry& r) {
  ComponentInfo info;
  info.name = "NormEngine";
  info.category = "Engine/Generate";
  info.description = "the norm of each vector of a list";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t == "Vec3d") return std::make_unique<NormEngine>();
    return nullptr;
  };
  r.add(std::move(info));
}

}  // namespace sinew
