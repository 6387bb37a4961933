// The haptic loop's report (`sinew run --haptics-report`): for every device
// driver in a graph, the distribution of its servo periods over a window of
// the steady clock (the run), and what its LCPForceFeedback did.
#pragma once

#include <cstdint>
#include <string>

namespace sinew {
class Node;
}

namespace sinew::haptics {

// One paragraph per driver, each starting with
// "haptic loop: N updates, period p50 … ms, p99 … ms, max … ms"; "haptic loop:
// no device served" when no driver runs a servo thread.
std::string haptics_report(const Node& root, std::int64_t from_ns, std::int64_t to_ns);

}  // namespace sinew::haptics
