#include "engine/pair_box_roi.h"

#include "core/registry.h"
#include "core/state_creator.h"

namespace sinew {

void register_pair_box_roi(Registry& r) {
  ComponentInfo info;
  info.name = "PairBoxROI";
  info.category = "Engine/Select";
  info.description = "selects the points between two nested boxes";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<PairBoxROI>();
  r.add(std::move(info));
}

}  // namespace sinew
