#include "constraint/response/distinct_outputs.h"

namespace sinew {

void keep_distinct_outputs(const std::vector<DetectionOutput>& outputs, std::vector<std::size_t>& kept) {
  kept.clear();
  const double min_dist2 = static_cast<double>(0.00000001f);  // SOFA's float constant
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const DetectionOutput& o = outputs[i];
    bool found = false;
    for (std::size_t k = 0; k < kept.size() && !found; ++k) {
      const DetectionOutput& p = outputs[kept[k]];
      found = (o.point1 - p.point1).squaredNorm() + (o.point2 - p.point2).squaredNorm() < min_dist2;
    }
    if (!found) kept.push_back(i);
  }
}

}  // namespace sinew
