#include "engine/generate/spiral.h"

#include <cmath>
#include <numbers>

#include "core/registry.h"

namespace sinew {

Spiral::Spiral() {
  add_input(&rest_position);
  add_input(&curvature);
  add_output(&position);
}

void Spiral::do_update() {
  const std::vector<Vec3>& x0 = rest_position.get();
  const double A = curvature.get();
  std::vector<Vec3>& x = position.edit();
  x.clear();
  x.reserve(x0.size());
  for (const Vec3& p : x0) {
    const double t0 = p[0];
    const double l = std::fabs(t0);
    double t = std::sqrt(l);
    for (int n = 0; n < 10; ++n) {
      const double lt = A / 2 * (t * std::sqrt(1 + t * t) + std::asinh(t));
      const double dlt = A * std::sqrt(1 + t * t);
      t -= (lt - l) / dlt;
    }
    const double r = t0 > 0 ? A * t : -A * t;
    Vec3 v(r * std::cos(t), r * std::sin(t), p[2]);
    Vec3 nrm(-A * std::sin(t) - A * t * std::cos(t), A * std::cos(t) - A * t * std::sin(t), 0);
    const double len = nrm.norm();
    if (len > 0) nrm /= len;
    // SOFA compares with the float 0.8f and stores it (0.800000011920929).
    if (t > -std::numbers::pi / 2 && t < std::numbers::pi / 2 && nrm[1] > static_cast<double>(0.8f)) {
      nrm[1] = static_cast<double>(0.8f);
      nrm[0] = -std::sqrt(1 - nrm[1] * nrm[1]);
    }
    x.push_back(v + nrm * p[1]);
  }
}

void register_spiral(Registry& r) {
  ComponentInfo info;
  info.name = "Spiral";
  info.category = "Engine/Generate";
  info.description = "rolls a straight strip (x: arc length) into an Archimedean spiral";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<Spiral>(); };
  r.add(std::move(info));
}

}  // namespace sinew
