// The topology comparer and its metric (regression-protocol.md §5, §7).
//
// For each compared block and each element type whose reference count n is
// non-zero (types with n = 0 are not checked, whatever the live topology has):
// if the live count m differs, add |n - m|; otherwise add 1 per element i < n
// whose vertex indices differ from the reference's in any position (no
// rotation or permutation invariance). A topology test passes iff the total
// is 0; `epsilon` plays no role.
#pragma once

#include <array>
#include <vector>

#include "regression/block_schedule.h"
#include "regression/topology_file.h"

namespace sinew::regression {

// Per-type error of one reference block against a live topology. An element
// whose reference indices are missing (short index line) counts as differing.
std::array<long long, kElementTypeCount> compare_topology_block(const TopologyBlock& reference,
                                                                const TopologyView& live);

// One reference file being compared against one live topology.
class TopologyComparer {
 public:
  explicit TopologyComparer(std::vector<TopologyBlock> blocks);

  // Call at the start of every step with the event time t (accumulated as
  // t(k+1) = t(k) + dt in double, starting at 0). Reads blocks while their time
  // is <= t + 1e-8 but compares only the last one whose time is <= t: a block
  // whose printed time is just above the clock (e.g. "0.1" at clock
  // 0.09999999999999999) is consumed and never compared, exactly as SOFA does.
  void on_step_begin(double t, const TopologyView& live);

  // Sum over compared blocks and types: the test passes iff this is 0.
  long long total_error() const;
  const std::array<long long, kElementTypeCount>& errors_by_type() const { return errors_; }
  int compared_blocks() const { return compared_; }
  // Printed times of the compared blocks, in order (diagnostics).
  const std::vector<double>& compared_times() const { return compared_times_; }

 private:
  std::vector<TopologyBlock> blocks_;
  BlockSchedule schedule_;
  std::array<long long, kElementTypeCount> errors_{};
  int compared_ = 0;
  std::vector<double> compared_times_;
};

}  // namespace sinew::regression
