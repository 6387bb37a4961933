#include "engine/analyze/hausdorff_distance.h"

#include <cmath>
#include <limits>

#include "core/registry.h"

namespace sinew {

namespace {
FlatVec flat(int w) {
  FlatVec v;
  v.width = w;
  return v;
}
// Largest distance from a point of `a` to its nearest point of `b` (0 when a is empty).
double directed(const FlatVec& a, const FlatVec& b) {
  const std::size_t w = static_cast<std::size_t>(a.width);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < b.size(); ++j) {
      double s = 0;
      for (std::size_t k = 0; k < w; ++k) {
        const double d = a.data[i * w + k] - b.data[j * w + k];
        s += d * d;
      }
      best = std::min(best, std::sqrt(s));
    }
    worst = std::max(worst, best);
  }
  return worst;
}
}  // namespace

HausdorffDistance::HausdorffDistance(int width)
    : points1(this, "points1", flat(width), "first point cloud", "Input", "length"),
      points2(this, "points2", flat(width), "second point cloud", "Input", "length") {
  listening.set(true);
  listening.unset();
}

void HausdorffDistance::compute() {
  const double a = directed(points1.get(), points2.get());
  const double b = directed(points2.get(), points1.get());
  d12.set(a);
  d21.set(b);
  max.set(b > a ? b : a);
}

void HausdorffDistance::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_begin && update.get()) compute();
}

void register_hausdorff_distance(Registry& r) {
  ComponentInfo info;
  info.name = "HausdorffDistance";
  info.category = "Engine/Analyze";
  info.description = "Hausdorff distances between two point clouds";
  info.templates = {"Vec3d", "Vec2d", "Vec1d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    return std::make_unique<HausdorffDistance>(t == "Vec1d" ? 1 : t == "Vec2d" ? 2 : 3);
  };
  r.add(std::move(info));
}

}  // namespace sinew
