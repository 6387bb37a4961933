#include "regression/state_compare.h"

#include <cmath>
#include <limits>

#include "regression/number_format.h"

namespace sinew::regression {
namespace {

std::vector<double> block_times(const std::vector<StateBlock>& blocks) {
  std::vector<double> times;
  times.reserve(blocks.size());
  for (const StateBlock& b : blocks) times.push_back(b.time);
  return times;
}

}  // namespace

double mean_abs_difference(std::span<const double> reference, std::span<const double> live) {
  double sum = 0.0;
  std::size_t k = 0;
  for (; k < reference.size() && k < live.size(); ++k) {
    // A non-finite live value prints as "nan"/"inf", which does not read back
    // as a number: SOFA's comparison of this vector ends there.
    if (!std::isfinite(live[k])) break;
    sum += std::fabs(reference[k] - round_g6(live[k]));
  }
  return k == 0 ? 0.0 : sum / static_cast<double>(k);
}

StateComparer::StateComparer(std::vector<StateBlock> blocks, double dt)
    : blocks_(std::move(blocks)), schedule_(block_times(blocks_)), margin_(0.001 * dt) {}

void StateComparer::on_step_begin(double t, const double* x, std::size_t nx, const double* v,
                                  std::size_t nv, std::size_t npoints) {
  const double limit = t + margin_;
  const auto due = schedule_.advance(limit, limit);
  if (!due) return;
  const StateBlock& block = blocks_[*due];
  double contribution = 0.0;
  for (const StateLine& line : block.lines) {
    const double* live = line.tag == 'X' ? x : v;
    const std::size_t n = live ? (line.tag == 'X' ? nx : nv) : 0;
    const double e = mean_abs_difference(line.values, std::span<const double>(live, n));
    total_error_ += e;
    if (npoints > 0) {
      // Added line by line (not per block) to keep SOFA's summation order.
      const double share = e / static_cast<double>(npoints);
      error_ += share;
      contribution += share;
    }
  }
  results_.push_back({block.time, t, contribution});
}

double scene_value(const std::vector<std::pair<double, int>>& errors_and_weights) {
  double sum = 0.0;
  double weights = 0.0;
  for (const auto& [error, weight] : errors_and_weights) {
    sum += weight * error;
    weights += weight;
  }
  if (weights == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return sum / weights;
}

bool scene_passes(double value, double epsilon) { return !(value > epsilon); }

}  // namespace sinew::regression
