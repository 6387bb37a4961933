#include "collision/response/outputs_by_id.h"

#include <algorithm>

namespace sinew {

void keep_smallest_per_id(const std::vector<DetectionOutput>& outputs,
                          std::vector<std::pair<std::int64_t, std::size_t>>& scratch, std::vector<std::size_t>& kept) {
  scratch.clear();
  for (std::size_t i = 0; i < outputs.size(); ++i) scratch.emplace_back(outputs[i].id, i);
  std::sort(scratch.begin(), scratch.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    const double va = outputs[a.second].value, vb = outputs[b.second].value;
    if (va != vb) return va < vb;
    return a.second < b.second;
  });
  kept.clear();
  for (std::size_t k = 0; k < scratch.size(); ++k)
    if (k == 0 || scratch[k].first != scratch[k - 1].first) kept.push_back(scratch[k].second);
  std::sort(kept.begin(), kept.end());
}

}  // namespace sinew
