#include "engine/merge_points.h"

#include <algorithm>

#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

MergePoints::MergePoints(StateType type)
    : position1(this, "position1", empty_coords(type), "coordinates of the first object", "Inputs"),
      position2(this, "position2", empty_coords(type), "coordinates of the second object", "Inputs"),
      points(this, "points", empty_coords(type), "the merged coordinates", "Outputs") {
  add_input(&position1);
  add_input(&position2);
  add_input(&mapping_x2);
  add_output(&indices1);
  add_output(&indices2);
  add_output(&points);
}

// Lazy, as SOFA's: the first read computes, so that a position2 filled by components initialised later (a
// mapped state in a child node) is complete by then.
void MergePoints::init() { set_dirty(); }

void MergePoints::do_update() {
  if (no_update.get() && done_) return;
  const FlatVec& x1 = position1.get();
  const FlatVec& x2 = position2.get();
  std::vector<unsigned>& i1 = indices1.edit();
  std::vector<unsigned>& i2 = indices2.edit();
  FlatVec& out = points.edit();
  i1.clear();
  i2.clear();
  out.width = x1.width;
  out.data.clear();
  const std::size_t w = static_cast<std::size_t>(x1.width);
  std::vector<unsigned> map = mapping_x2.get();
  if (mapping_x2.is_set() && !map.empty()) {  // injection
    out.data = x1.data;
    const std::size_t n = x1.size();
    for (std::size_t i = 0; i < map.size(); ++i) {
      if (map[i] >= n) {
        msg_error("mappingX2[" + std::to_string(i) + "] = " + std::to_string(map[i]) + " is beyond the " +
                  std::to_string(n) + " points of position1");
      } else if (i >= x2.size()) {
        msg_error("mappingX2[" + std::to_string(i) + "]: position2 has only " + std::to_string(x2.size()) +
                  " points");
      } else {
        std::copy_n(&x2.data[i * w], w, &out.data[map[i] * w]);
      }
    }
    std::sort(map.begin(), map.end());
    std::size_t j = 0;
    for (unsigned i = 0; i < n; ++i) {
      if (j < map.size() && map[j] == i) {
        i2.push_back(i);
        ++j;
      } else {
        i1.push_back(i);
      }
    }
  } else {  // addition
    out.data = x1.data;
    out.data.insert(out.data.end(), x2.data.begin(), x2.data.end());
    const unsigned n1 = static_cast<unsigned>(x1.size());
    for (unsigned i = 0; i < n1; ++i) i1.push_back(i);
    for (unsigned i = 0; i < x2.size(); ++i) i2.push_back(n1 + i);
  }
  done_ = true;
}

void register_merge_points(Registry& r) {
  ComponentInfo info;
  info.name = "MergePoints";
  info.category = "Engine/Generate";
  info.description = "merges two coordinate vectors: appended, or the second injected into the first";
  info.templates = {"Vec3d", "Vec1d", "Vec2d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<MergePoints>();
  r.add(std::move(info));
}

}  // namespace sinew
