// The detection outputs a Lagrangian contact response keeps: an output whose
// two points are both within 1e-4 (squared distances summed below SOFA's
// float constant 1e-8) of an output already kept is a duplicate and dropped,
// in output order (SOFA's unilateral and stick contact responses).
#pragma once

#include <cstddef>
#include <vector>

#include "collision/detection_output.h"

namespace sinew {

// Fills `kept` with the indices of the distinct outputs (cleared first; its capacity is reused).
void keep_distinct_outputs(const std::vector<DetectionOutput>& outputs, std::vector<std::size_t>& kept);

}  // namespace sinew
