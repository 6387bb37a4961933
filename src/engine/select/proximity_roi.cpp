#include "engine/select/proximity_roi.h"

#include <algorithm>
#include <limits>

#include "core/node.h"
#include "core/registry.h"
#include "io/mesh_loader.h"

namespace sinew {

ProximityROI::ProximityROI() {
  indices.add_alias("pointIndices");
  position.add_alias("rest_position");
  add_input(&position);
  add_input(&centers);
  add_input(&radii);
  add_input(&n);
  add_output(&indices);
  add_output(&points_in_roi);
  add_output(&distance);
  add_output(&indices_out);
}

void ProximityROI::init() {
  if (!position.is_set() && !position.parent()) {
    if (auto* ms = node()->find_up<MechanicalState>()) {
      if (BaseField* f = ms->find_field("rest_position")) position.set_parent(f);
    } else if (auto* loader = node()->find_up<MeshLoader>()) {
      position.set_parent(&loader->position);
    }
  }
  set_dirty();  // computed when an output is read, as SOFA
}

namespace {
struct SortingPair {
  unsigned i;
  double distance;
  bool operator<(const SortingPair& p) const { return distance < p.distance; }
};
}  // namespace

void ProximityROI::do_update() {
  const std::vector<Vec3>& c = centers.get();
  if (c.empty()) return;
  std::vector<double> r = radii.get();
  if (r.empty()) {
    msg_error("'radii' must hold at least one value: the ROI does nothing");
    return;
  }
  const unsigned N = n.get();
  if (N == 0) {
    msg_error("'N' must be greater than zero: the ROI does nothing");
    return;
  }
  if (c.size() > r.size()) {
    r.resize(c.size(), r.back());
    radii.set(r);
  }
  if (c.size() < r.size()) msg_error("'radii' has more values than 'centers'");

  const std::vector<Vec3>& x = position.get();
  std::vector<unsigned>& in = indices.edit();
  std::vector<unsigned>& out = indices_out.edit();
  std::vector<Vec3>& pin = points_in_roi.edit();
  std::vector<double>& dist = distance.edit();
  in.clear();
  out.clear();
  pin.clear();
  dist.clear();

  std::vector<SortingPair> heap;
  for (unsigned i = 0; i < x.size(); ++i) {
    double mindist = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < c.size(); ++j) {
      const double d = (c[j] - x[i]).norm();
      if (d < r[j] && mindist > d) mindist = d;
    }
    if (mindist == std::numeric_limits<double>::max()) {
      out.push_back(i);
      continue;
    }
    if (heap.empty()) {
      heap.push_back({i, mindist});
      std::push_heap(heap.begin(), heap.end());
      continue;
    }
    if (heap.front().distance >= mindist) {
      if (heap.size() >= N) {
        std::pop_heap(heap.begin(), heap.end());
        const unsigned evicted = heap.back().i;
        heap.pop_back();
        // SOFA reads its reference to the top after the pop: the new top's index
        // (the evicted one's when the heap held one point).
        out.push_back(heap.empty() ? evicted : heap.front().i);
      }
      heap.push_back({i, mindist});
      std::push_heap(heap.begin(), heap.end());
    } else if (heap.size() < N) {
      heap.push_back({i, mindist});
      std::push_heap(heap.begin(), heap.end());
    } else {
      out.push_back(i);
    }
  }
  for (const SortingPair& p : heap) {
    in.push_back(p.i);
    dist.push_back(p.distance);
    pin.push_back(x[p.i]);
  }
}

void register_proximity_roi(Registry& r) {
  ComponentInfo info;
  info.name = "ProximityROI";
  info.category = "Engine/Select";
  info.description = "the N points nearest to the centres of spheres containing them";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<ProximityROI>(); };
  r.add(std::move(info));
}

}  // namespace sinew
