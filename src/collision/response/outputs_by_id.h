// Which detection outputs SOFA's barycentric contacts (penalty and stick) turn
// into contact points: one per output id, the first of smallest value, kept at
// its own place in the output order.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "collision/detection_output.h"

namespace sinew {

// `kept` receives the indices of the kept outputs, increasing; `scratch` is
// working memory (its capacity is reused from step to step).
void keep_smallest_per_id(const std::vector<DetectionOutput>& outputs,
                          std::vector<std::pair<std::int64_t, std::size_t>>& scratch, std::vector<std::size_t>& kept);

}  // namespace sinew
