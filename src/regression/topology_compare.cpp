#include "regression/topology_compare.h"

namespace sinew::regression {
namespace {

// SOFA's read loop looks this far past the clock, but keeps only blocks at or
// before the clock (see on_step_begin).
constexpr double kReadMargin = 1e-8;

std::vector<double> block_times(const std::vector<TopologyBlock>& blocks) {
  std::vector<double> times;
  times.reserve(blocks.size());
  for (const TopologyBlock& b : blocks) times.push_back(b.time);
  return times;
}

}  // namespace

std::array<long long, kElementTypeCount> compare_topology_block(const TopologyBlock& reference,
                                                                const TopologyView& live) {
  std::array<long long, kElementTypeCount> errors{};
  for (std::size_t type = 0; type < kElementTypeCount; ++type) {
    const long long n = reference.counts[type];
    if (n == 0) continue;
    const long long m = static_cast<long long>(live.count(type));
    if (n != m) {
      errors[type] = n > m ? n - m : m - n;
      continue;
    }
    const std::size_t k = kVerticesPerElement[type];
    const std::vector<long long>& ref = reference.indices[type];
    const auto& cur = live.indices[type];
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
      bool differs = ref.size() < (i + 1) * k;
      for (std::size_t j = 0; j < k && !differs; ++j) {
        differs = ref[i * k + j] != static_cast<long long>(cur[i * k + j]);
      }
      if (differs) ++errors[type];
    }
  }
  return errors;
}

TopologyComparer::TopologyComparer(std::vector<TopologyBlock> blocks)
    : blocks_(std::move(blocks)), schedule_(block_times(blocks_)) {}

void TopologyComparer::on_step_begin(double t, const TopologyView& live) {
  const auto due = schedule_.advance(t + kReadMargin, t);
  if (!due) return;
  const auto errors = compare_topology_block(blocks_[*due], live);
  for (std::size_t type = 0; type < kElementTypeCount; ++type) errors_[type] += errors[type];
  ++compared_;
  compared_times_.push_back(blocks_[*due].time);
}

long long TopologyComparer::total_error() const {
  long long total = 0;
  for (long long e : errors_) total += e;
  return total;
}

}  // namespace sinew::regression
